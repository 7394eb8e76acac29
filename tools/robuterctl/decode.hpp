// Replies decoded for people: names and units for each field of the seed's and extension replies.
#pragma once

#include <string>

namespace robuter::ctl {

// A one-or-more-line explanation of `reply` given the command `sent`; the reply itself when
// there is nothing to add.
std::string describe_reply(const std::string& sent, const std::string& reply);

// True when an XE reply reports a latched or held emergency; `what` gets a banner for it.
bool emergency_banner(const std::string& xe_reply, std::string& what);

}  // namespace robuter::ctl
