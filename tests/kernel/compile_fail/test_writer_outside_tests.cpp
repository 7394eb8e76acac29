// SPDX-License-Identifier: GPL-3.0-or-later
// Must NOT compile: firmware code (no tests/support header) asks for the tests' writer access.
#include "kernel/blackboard.hpp"

struct Posture {
  int x = 0;  // 0.1 mm
};
class Executor;  // the owner
using PostureTopic = robuter::Topic<Posture, Executor>;

int main() {
  PostureTopic t;
  robuter::Writer<Posture> w = robuter::TestWriterAccess<PostureTopic>::writer(t);  // error: incomplete type
  w.publish(Posture{1});
}
