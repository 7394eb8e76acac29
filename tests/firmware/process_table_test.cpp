// SPDX-License-Identifier: GPL-3.0-or-later
// The real default process table (Betaflight's scheduler tests check the real table too) and the
// start-up check that every blackboard topic has exactly one writer.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "modules/firmware/process_table.hpp"
#include "modules/firmware/sim_firmware.hpp"
#include "modules/firmware/topic_claims.hpp"
#include "tests/support/test_writer.hpp"

namespace robuter {
namespace {

const DefaultRow& row_named(std::string_view name) {
  for (const DefaultRow& r : default_table())
    if (name == r.name) return r;
  ADD_FAILURE() << "no default row " << name;
  return default_table().front();
}

// The seed's kernel.c rows as decided (docs/ARCHITECTURE.md): serial 2/0, executor 10/2,
// emergency 10/4, and, within a shared tick, emergency before executor before serial before
// the ring (seed priorities 5, 4, 3, 2); the ring read every tick (the seed's 4/6 made faster).
TEST(ProcessTable, TheSeedsRowsKeepTheirPeriodsOffsetsAndOrder) {
  const DefaultRow& serial = row_named("serial");
  const DefaultRow& executor = row_named("executor");
  const DefaultRow& emergency = row_named("emergency");
  const DefaultRow& us = row_named("us");
  EXPECT_EQ(serial.period, 2u);
  EXPECT_EQ(serial.offset, 0u);
  EXPECT_EQ(executor.period, 10u);
  EXPECT_EQ(executor.offset, 2u);
  EXPECT_EQ(emergency.period, 10u);
  EXPECT_EQ(emergency.offset, 4u);
  EXPECT_EQ(us.period, 1u);
  EXPECT_EQ(emergency.priority, 5);
  EXPECT_EQ(executor.priority, 4);
  EXPECT_EQ(serial.priority, 3);
  EXPECT_EQ(us.priority, 2);
  // The world moves first in a tick, then the CAN bus's frames come in, before any module reads.
  const DefaultRow& sim = row_named("sim");
  const DefaultRow& can = row_named("can");
  for (const DefaultRow& r : default_table()) {
    if (&r != &sim) {
      EXPECT_GT(sim.priority, r.priority) << r.name;
    }
    if (&r != &sim && &r != &can) {
      EXPECT_GT(can.priority, r.priority) << r.name;
    }
  }
  // The automatic modes decide after the safety core and the link in a shared tick: a mode's
  // request is judged by the emergency module at its next run, never before the operator's.
  for (const char* mode : {"planner", "gate", "doors", "demo", "localise"})
    EXPECT_LT(row_named(mode).priority, serial.priority) << mode;
}

// Every default row passes the kernel's own validation at the default tick, and its budget fits
// its period; names are unique.
TEST(ProcessTable, EveryDefaultRowIsValidAtTheDefaultTick) {
  Config cfg;
  std::set<std::string> names;
  struct Idle final : Process {
    void run(Kernel&) override {}
  } idle;
  std::vector<ProcessRow> rows;
  for (const DefaultRow& r : default_table()) {
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_LE(static_cast<std::uint64_t>(r.budget_us), static_cast<std::uint64_t>(r.period) * cfg.kernel.tick_us)
        << r.name;
    rows.push_back(ProcessRow{r.name, &idle, r.period, r.offset, r.priority, r.budget_us});
  }
  VirtualClock clock;
  Kernel k(clock, static_cast<Nanos>(cfg.kernel.tick_us) * kNanosPerMicro);
  EXPECT_EQ(k.validate(rows), std::nullopt);
}

// The firmware robuterd --sim composes runs the default rows as they are (the CAN row is the
// hardware's, the localisation's off by default), each with its module.
TEST(ProcessTable, TheSimulatedFirmwareRunsTheDefaultRows) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  Kernel& k = fw.kernel();
  std::set<std::string> composed;
  for (std::size_t i = 0; i < k.process_count(); ++i) {
    const ProcessRow& row = k.row(i);
    composed.insert(row.name);
    EXPECT_NE(row.process, nullptr) << row.name;
    bool found = false;
    for (const DefaultRow& d : default_table()) {
      if (std::string_view(d.name) != row.name) continue;
      found = true;
      EXPECT_EQ(row.period, d.period) << row.name;
      EXPECT_EQ(row.offset, d.offset) << row.name;
      EXPECT_EQ(row.priority, d.priority) << row.name;
      EXPECT_EQ(row.budget_us, d.budget_us) << row.name;
    }
    EXPECT_TRUE(found) << "a row not in the default table: " << row.name;
  }
  for (const DefaultRow& d : default_table()) {
    const bool expected = std::string_view(d.name) != "can" && std::string_view(d.name) != "localise";
    EXPECT_EQ(composed.count(d.name) == 1, expected) << d.name;
  }
}

// The composed firmware claimed every topic's writer exactly once (the localisation's is not
// composed by default, so its topic has no writer).
TEST(TopicClaims, TheComposedFirmwareClaimedEachTopicOnce) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  int topics = 0;
  fw.bb().for_each_topic([&](std::string_view name, const auto& t) {
    ++topics;
    EXPECT_EQ(t.claims(), name == "localisation" ? 0 : 1) << name;
  });
  EXPECT_EQ(topics, 32);  // every Topic member of struct Blackboard (tests/docs checks the names against it)
  const std::string_view unowned[] = {"localisation"};
  EXPECT_EQ(topic_claims_error(fw.bb(), unowned), std::nullopt);
}

// A second writer of a topic, or a topic nobody writes, is a start-up error naming the topic.
TEST(TopicClaims, ASecondWriterOrAMissingOneIsNamed) {
  Blackboard bb;
  std::vector<std::string_view> others;
  bb.for_each_topic([&](std::string_view name, const auto&) {
    if (name != "ranges" && name != "posture") others.push_back(name);
  });
  // Claim every topic once, through the tests' accessor, except posture; claim ranges twice.
  bb.for_each_topic([&](std::string_view, auto& t) { (void)test_writer(t); });
  (void)test_writer(bb.ranges);
  // posture was claimed above too; ask the check to expect it unclaimed, as if its owner were absent.
  const std::string_view absent[] = {"posture"};
  const auto err = topic_claims_error(bb, absent);
  ASSERT_TRUE(err.has_value());
  EXPECT_NE(err->find("ranges claimed 2 times (want 1)"), std::string::npos) << *err;
  EXPECT_NE(err->find("posture claimed 1 times (want 0)"), std::string::npos) << *err;
  for (std::string_view n : others) EXPECT_EQ(err->find(std::string(n) + " claimed"), std::string::npos) << n;
  Blackboard fresh;
  const auto none = topic_claims_error(fresh);
  ASSERT_TRUE(none.has_value());
  EXPECT_NE(none->find("heartbeat claimed 0 times (want 1)"), std::string::npos) << *none;
}

// A payload field named `seq` (the counter the requests carried), checked on the topic's struct.
template <typename T>
constexpr bool kCarriesSeq = requires(const T& t) { t.seq; };

// modules/topics.hpp: a new request is a new generation of its topic; no payload counter repeats
// it (a reader that needs "new?" asks updated() or generation(), a writer waiting for the effect
// compares its Writer::generation() with what the owner echoes).
TEST(Topics, NoRequestRepeatsItsGenerationInAPayloadCounter) {
  EXPECT_FALSE(kCarriesSeq<MotionRequest>);
  EXPECT_FALSE(kCarriesSeq<ServoRequest>);
  EXPECT_FALSE(kCarriesSeq<OdometrySet>);
  EXPECT_FALSE(kCarriesSeq<GoToRequest>);
  EXPECT_FALSE(kCarriesSeq<ModeRequest>);
  EXPECT_FALSE(kCarriesSeq<MotionCommand>);
  EXPECT_FALSE(kCarriesSeq<PlannerGoal>);
  EXPECT_FALSE(kCarriesSeq<LocaliseRequest>);
}

// The echoes that stay are generations of the topic they answer: after AC, ASN and AM through
// the link, the posture carries exactly the generations the link and the emergency module wrote.
TEST(Topics, OwnersEchoTheGenerationTheyActedOn) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("AC 1000 2000 0"), "ack");
  ASSERT_EQ(fw.ask("AC 3000 2000 0"), "ack");
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("AM 10 10"), "ack");
  fw.run_ticks(5);
  const Blackboard& bb = fw.bb();
  EXPECT_EQ(bb.posture.reader().peek().odometry_seq, bb.odometry_set.reader().generation());
  EXPECT_EQ(bb.odometry_set.reader().generation(), 2u);
  EXPECT_EQ(bb.posture.reader().peek().command_seq, bb.motion_command.reader().generation());
}

}  // namespace
}  // namespace robuter
