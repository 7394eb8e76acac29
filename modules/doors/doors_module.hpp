// Door-crossing module (Ad / Af): runs DoorCrossing with the ultrasonic and communication
// emergencies off, and restores them on every way out.
#pragma once

#include <cstdint>

#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/doors/crossing.hpp"
#include "modules/ptu/motion_claim.hpp"
#include "modules/topics.hpp"

namespace robuter {

class EmergencyModule;

// Starts on Ad, or when the passage finder reports "aligned" and [gate] hand_over is on. While
// it crosses, the emergency module's mask is [doors] emergency_mask (bumper only, as the seed's
// emerg.on = BUMPER); the mask found at the start is put back when the crossing ends — crossed,
// can't cross, Af, an emergency, another motion source, the pan-tilt failing, every link closed,
// the time limit, or the firmware stopping (close()).
class DoorsModule final : public Process {
 public:
  DoorsModule(Blackboard& bb, const Config& cfg, EmergencyModule* emergency);

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

  const doors::DoorCrossing& crossing() const { return crossing_; }
  bool mask_lowered() const { return lowered_; }

 private:
  void begin(std::uint64_t tick);
  // Puts the saved mask back (once per crossing).
  void restore_mask();
  void publish(Kernel& k, const doors::CrossingOutput& o);

  doors::DoorCrossing crossing_;
  EmergencyModule* emergency_;        // whose mask is lowered (null: none, e.g. tests)
  std::uint8_t crossing_mask_;        // detections kept while crossing
  bool hand_over_;                    // start when the passage finder is aligned
  Reader<ModeRequest> modes_;
  Reader<PanTiltScan> scan_;
  Reader<ModeStatus> ptu_;
  Reader<ModeStatus> gate_;
  Reader<Posture> posture_;
  Reader<LinkStatus> link_;
  MotionClaim claim_;
  Writer<MotionRequest> motion_out_;
  Writer<ModeStatus> status_out_;
  std::uint32_t seen_modes_ = 0;      // ModeRequest.doors_seq last acted on
  ModeState gate_seen_ = ModeState::off;  // gate state at the previous activation
  bool lowered_ = false;              // the mask is ours: restore it at the end
  std::uint8_t saved_mask_ = 7;       // the mask before the crossing
  bool had_link_ = false;             // a link was open at the start
  bool sent_stop_ = true;             // the final zero request went out
};

}  // namespace robuter
