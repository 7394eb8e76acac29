// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware's one vocabulary: the enums that cross topics and the link, each with its words from one list.
#pragma once

#include <cstdint>
#include <string_view>

#include "kernel/vocabulary.hpp"
#include "protocol/codec/limits.hpp"

// The enums that cross the link are worded with kernel/vocabulary.hpp's X-macro lists, and each
// word is also one token of a reply: no blank, no '*', at most kMaxTokenLength bytes.
#define ROBUTER_REPLY_VOCABULARY(Enum, LIST, fallback_word) \
  ROBUTER_VOCABULARY(Enum, LIST, fallback_word);           \
  static_assert(::robuter::words_are_tokens<Enum>(kMaxTokenLength), #Enum ": every word is one token of a reply")

namespace robuter::protocol {

// The generic part, as the protocol's code names it (`protocol::word`, …).
using ::robuter::from_word;
using ::robuter::kEnumerators;
using ::robuter::word;

// ---- detections: the bits of XE's mask, of [emergency] mask and of the gate (the seed's emerg.on) ----
inline constexpr std::uint8_t kDetectBumper = 1;      // collision sensed by the contact bumpers
inline constexpr std::uint8_t kDetectUltrasonic = 2;  // watch-dog sensors under the safety distance
inline constexpr std::uint8_t kDetectComm = 4;        // link silent for longer than the communication limit
inline constexpr std::uint8_t kDetectAll = kDetectBumper | kDetectUltrasonic | kDetectComm;  // every detection

// ---- words that stand for no enumerator ----
inline constexpr std::string_view kAbsentWord = "absent";  // XD: the mode's module is not running
inline constexpr std::string_view kNoPhaseWord = "none";   // XD: no demonstration phase (off or absent)

// What started the emergency in force (XE, the emergency module's log); the last cause while
// latched. The last three come from the drives' bus (docs/CAN.md).
#define ROBUTER_EMERGENCY_CAUSES(X)                                                                    \
  X(none, "none")                     /* no emergency */                                               \
  X(bumper, "bumper")                 /* collision sensed by the bumper */                             \
  X(obstacle, "obstacle")             /* ultrasonic reading under the safety distance */               \
  X(comm_loss, "comm-loss")           /* no message for longer than the communication limit */         \
  X(stop_byte, "stop-byte")           /* the client sent the immediate stop byte (0x18) */             \
  X(motion_timeout, "motion-timeout") /* moving, and no motion command within the freshness time */   \
  X(drive_fault, "drive-fault")       /* the motor drive reports a fault or stopped answering */       \
  X(other, "other")                   /* anything else (a module fault, ...) */                        \
  X(heartbeat_lost, "heartbeat-lost") /* a motor drive stopped sending its CAN heartbeat */            \
  X(bus_passive, "bus-error-passive") /* the drives' CAN bus went error-passive */                     \
  X(bus_off, "bus-off")               /* the CAN controller went bus-off */
enum class EmergencyCause : std::uint8_t { ROBUTER_EMERGENCY_CAUSES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_REPLY_VOCABULARY(EmergencyCause, ROBUTER_EMERGENCY_CAUSES, "other");

// What the grid planner is doing (XP, the planner's log).
#define ROBUTER_PLANNER_STATES(X)                                                                      \
  X(idle, "idle")               /* no goal yet */                                                      \
  X(scanning, "scanning")       /* stopped, waiting for fresh ring data */                             \
  X(planning, "planning")       /* a plan is due this activation */                                    \
  X(moving, "moving")           /* following the visible prefix of the path */                         \
  X(crossing, "crossing")       /* XQ: the robot lent to the door crossing at a narrow door */         \
  X(reached, "reached")         /* at the goal (within the tolerance) */                               \
  X(unreachable, "unreachable") /* no path on the current map (or the goal cell is an obstacle) */     \
  X(blocked, "blocked")         /* the robot's own place is an obstacle: no plan starts from here */   \
  X(outside, "outside")         /* the robot is off the planner's map */                               \
  X(stopped, "stopped")         /* an emergency ended the navigation */                                \
  X(cancelled, "cancelled")     /* XH */                                                               \
  X(operator_ended, "operator") /* an operator's command (AM, AS, AW, the stop byte, …) took the robot */
enum class PlannerState : std::uint8_t { ROBUTER_PLANNER_STATES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_REPLY_VOCABULARY(PlannerState, ROBUTER_PLANNER_STATES, "idle");

// What the localisation is doing (XW; docs/LOCALISATION.md, "The module").
#define ROBUTER_LOCALISE_STATES(X)                                                                     \
  X(off, "off")             /* no localisation: no map, or [localise] enabled = false */               \
  X(searching, "searching") /* a global search (XA without a pose): the estimate is not yet one pose */ \
  X(uncertain, "uncertain") /* the particles spread or split: the map frame keeps its last correction */ \
  X(tracking, "tracking")   /* one compact cluster: the estimate corrects the map frame */
enum class LocaliseState : std::uint8_t { ROBUTER_LOCALISE_STATES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_REPLY_VOCABULARY(LocaliseState, ROBUTER_LOCALISE_STATES, "off");

// What the pan-tilt, passage-finder, door-crossing or demonstration module is doing (XD).
#define ROBUTER_MODE_STATES(X)                                                                         \
  X(off, "off")             /* not asked for (or ended and reset) */                                   \
  X(starting, "starting")   /* pan-tilt: start-up sequence; doors: waiting for a fresh scan */         \
  X(scanning, "scanning")   /* pan-tilt: sweeping and firing */                                        \
  X(searching, "searching") /* gate: stopped, waiting for a fresh scan to find the passage */          \
  X(moving, "moving")       /* gate: manoeuvring to the passage's centre line */                       \
  X(aligned, "aligned")     /* gate: stopped on the centre line facing the passage (done) */           \
  X(crossing, "crossing")   /* doors: moving through */                                                \
  X(waiting, "waiting")     /* doors: blocked on both sides, waiting for fresh readings */             \
  X(leaving, "leaving")     /* doors: through; driving on until the body is clear */                   \
  X(crossed, "crossed")     /* doors: done */                                                          \
  X(failed, "failed")       /* ended without success: see the reason */                                \
  X(running, "running")     /* demonstration: driving the course */                                    \
  X(finished, "finished")   /* demonstration: every lap driven, stopped (done) */
enum class ModeState : std::uint8_t { ROBUTER_MODE_STATES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_REPLY_VOCABULARY(ModeState, ROBUTER_MODE_STATES, "off");

// Why a mode failed or ended (XD).
#define ROBUTER_MODE_REASONS(X)                                                                        \
  X(none, "none")                     /* not failed */                                                 \
  X(no_unit, "no-unit")               /* pan-tilt: no port configured or it could not be opened */     \
  X(unit_silent, "unit-silent")       /* pan-tilt: the unit stopped answering */                       \
  X(unit_garbage, "unit-garbage")     /* pan-tilt: the unit's replies are not the protocol's */        \
  X(unit_refused, "unit-refused")     /* pan-tilt: the unit refused a command ("!") */                 \
  X(unit_lost, "unit-lost")           /* pan-tilt: its port went away */                               \
  X(no_passage, "no-passage")         /* gate: no passage locked within the time-out */                \
  X(cannot_align, "cannot-align")     /* gate: no alignment within the allowed manoeuvres */           \
  X(cant_cross, "cant-cross")         /* doors: blocked on both sides for longer than the wait */      \
  X(emergency, "emergency")           /* an emergency stopped the robot */                             \
  X(operator_motion, "operator")      /* a newer motion request from the link took over */             \
  X(scanner, "scanner")               /* the pan-tilt failed under the mode */                         \
  X(cancelled, "cancelled")           /* AT / Af (or Ag while a mode needed the scanner) */            \
  X(link_lost, "link-lost")           /* doors: every command link closed */                           \
  X(timeout, "timeout")               /* doors: the crossing took longer than its limit */             \
  X(shutdown, "shutdown")             /* the firmware stopped */                                       \
  X(no_landmark, "no-landmark")       /* demonstration: the calibration boxes were not found in time */ \
  X(protective, "protective")         /* go-to: a protective stop forgot the operator's motion */
enum class ModeReason : std::uint8_t { ROBUTER_MODE_REASONS(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_REPLY_VOCABULARY(ModeReason, ROBUTER_MODE_REASONS, "none");

// Where the demonstration course is (XD; seed dem.c, modules/demo/course.hpp).
#define ROBUTER_DEMO_PHASES(X)                                                                         \
  X(wait, "wait")       /* waiting for the ring's first scan */                                        \
  X(out, "out")         /* the straight leg out from the recalibration point */                        \
  X(turn, "turn")       /* the first half-circle */                                                    \
  X(lane, "lane")       /* the lane back towards the calibration boxes */                              \
  X(align, "align")     /* calibration 1: turning on one wheel until the side sensors read alike */    \
  X(advance, "advance") /* calibration 2: on to DISTX from the front box */                            \
  X(circle, "circle")   /* calibration 3: the half-circle back to the recalibration point */          \
  X(done, "done")       /* every lap driven, or stopped */                                             \
  X(failed, "failed")   /* the calibration boxes were not found in time */
enum class DemoPhase : std::uint8_t { ROBUTER_DEMO_PHASES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_REPLY_VOCABULARY(DemoPhase, ROBUTER_DEMO_PHASES, "done");

}  // namespace robuter::protocol
