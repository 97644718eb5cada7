// Step timing split in two halves: the task side plans step events into a
// single-producer single-consumer queue; the interrupt side (Tick) executes
// the events that are due, drives the coils and counts positions.
#ifndef CUBE_CORE_STEPPER_H_
#define CUBE_CORE_STEPPER_H_

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "hal.h"

namespace cube {

struct StepEvent {
  uint64_t due_us = 0;
  int8_t left = 0;   // -1, 0 or +1 step of the left wheel
  int8_t right = 0;  // -1, 0 or +1 step of the right wheel
  uint32_t generation = 0;
};

// Lock-free SPSC ring: Push() from the task, Front()/Pop() from the ISR.
class StepQueue {
 public:
  static constexpr size_t kCapacity = 128;

  bool Push(const StepEvent& e);
  bool Front(StepEvent* e) const;
  void Pop();
  size_t Size() const;
  bool Full() const { return Size() >= kCapacity; }

 private:
  StepEvent slots_[kCapacity];
  std::atomic<uint32_t> head_{0};  // written by the producer
  std::atomic<uint32_t> tail_{0};  // written by the consumer
};

// 28BYJ-48 half-step coil patterns, IN1..IN4 in bits 0..3.
extern const uint8_t kHalfStepPatterns[8];

class StepExecutor {
 public:
  // `right_mirrored`: the right motor is mounted facing the other way, so a
  // forward wheel step turns its shaft the other way round.
  StepExecutor(MotorDriver& motors, bool right_mirrored);

  // ISR context: executes every event of the current generation that is due
  // at `now_us`, discards events of older generations, and applies the coil
  // power state.
  void Tick(uint64_t now_us);

  // Task context.
  StepQueue& queue() { return queue_; }
  uint32_t generation() const { return generation_.load(); }
  // Invalidates every queued event (an immediate stop).
  void Cancel() { generation_.fetch_add(1); }
  void SetCoilsEnabled(bool on) { coils_wanted_.store(on); }
  // Whether the coils are energised, as applied by the last Tick().
  bool coils_on() const { return coils_applied_.load(); }
  // Whether the task side wants them energised (applied at the next Tick).
  bool coils_wanted() const { return coils_wanted_.load(); }
  // Signed positions in steps, wrapping at 2^32.
  int32_t left_position() const { return left_pos_.load(); }
  int32_t right_position() const { return right_pos_.load(); }

 private:
  void StepWheel(Wheel w, int dir);

  MotorDriver& motors_;
  bool right_mirrored_;
  StepQueue queue_;
  std::atomic<uint32_t> generation_{0};
  std::atomic<bool> coils_wanted_{false};
  std::atomic<bool> coils_applied_{false};
  std::atomic<int32_t> left_pos_{0};
  std::atomic<int32_t> right_pos_{0};
  uint8_t phase_[2] = {0, 0};
};

}  // namespace cube

#endif  // CUBE_CORE_STEPPER_H_
