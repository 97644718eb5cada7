#include "stepper.h"

namespace cube {

const uint8_t kHalfStepPatterns[8] = {0x1, 0x3, 0x2, 0x6, 0x4, 0xC, 0x8, 0x9};

bool StepQueue::Push(const StepEvent& e) {
  const uint32_t head = head_.load(std::memory_order_relaxed);
  const uint32_t tail = tail_.load(std::memory_order_acquire);
  if (head - tail >= kCapacity) return false;
  slots_[head % kCapacity] = e;
  head_.store(head + 1, std::memory_order_release);
  return true;
}

CUBE_ISR_FN bool StepQueue::Front(StepEvent* e) const {
  const uint32_t tail = tail_.load(std::memory_order_relaxed);
  const uint32_t head = head_.load(std::memory_order_acquire);
  if (head == tail) return false;
  *e = slots_[tail % kCapacity];
  return true;
}

CUBE_ISR_FN void StepQueue::Pop() {
  const uint32_t tail = tail_.load(std::memory_order_relaxed);
  tail_.store(tail + 1, std::memory_order_release);
}

size_t StepQueue::Size() const {
  return static_cast<size_t>(head_.load(std::memory_order_acquire) -
                             tail_.load(std::memory_order_acquire));
}

StepExecutor::StepExecutor(MotorDriver& motors, bool right_mirrored)
    : motors_(motors), right_mirrored_(right_mirrored) {}

CUBE_ISR_FN void StepExecutor::StepWheel(Wheel w, int dir) {
  const size_t i = static_cast<size_t>(w);
  int shaft = dir;
  if (w == Wheel::kRight && right_mirrored_) shaft = -dir;
  phase_[i] = static_cast<uint8_t>((phase_[i] + (shaft > 0 ? 1 : 7)) & 7);
  motors_.WriteCoils(w, kHalfStepPatterns[phase_[i]]);
  std::atomic<int32_t>& pos = w == Wheel::kLeft ? left_pos_ : right_pos_;
  // Wrapping add done in unsigned arithmetic.
  const uint32_t p = static_cast<uint32_t>(pos.load(std::memory_order_relaxed));
  pos.store(static_cast<int32_t>(p + static_cast<uint32_t>(dir)),
            std::memory_order_release);
}

CUBE_ISR_FN void StepExecutor::Tick(uint64_t now_us) {
  const bool want = coils_wanted_.load();
  if (want != coils_applied_.load()) {
    if (want) {
      motors_.WriteCoils(Wheel::kLeft, kHalfStepPatterns[phase_[0]]);
      motors_.WriteCoils(Wheel::kRight, kHalfStepPatterns[phase_[1]]);
    } else {
      motors_.WriteCoils(Wheel::kLeft, 0);
      motors_.WriteCoils(Wheel::kRight, 0);
    }
    coils_applied_.store(want);
  }
  const uint32_t gen = generation_.load();
  StepEvent e;
  while (queue_.Front(&e)) {
    if (e.generation != gen) {
      queue_.Pop();
      continue;
    }
    if (e.due_us > now_us) break;
    if (e.left != 0) StepWheel(Wheel::kLeft, e.left);
    if (e.right != 0) StepWheel(Wheel::kRight, e.right);
    coils_applied_.store(true);
    queue_.Pop();
  }
}

}  // namespace cube
