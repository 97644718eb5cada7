/**
 * What a trial reads from the robot it runs on, besides its HAL: where the robot is (the
 * simulator's ground truth, or on a robot only what the robot reports), how far it went, its
 * clock and its e-stop latch. The executor and the checks read nothing else, so a trial runs the
 * same on the simulator and on a robot.
 */
export interface TrialBody {
  /** `truth`: the simulator's ground truth; `reported`: what the robot itself reports. */
  readonly source: 'truth' | 'reported';
  /** Where the robot is now, metres and radians, in the trial's frame (read at once). */
  pose(): { x: number; y: number; yaw: number };
  /** Runs one call and measures it: the distance the centre travelled during it, metres. */
  around<T>(run: () => Promise<T>): Promise<{ result: T; pathM: number }>;
  /** The robot's clock since the trial began, µs. */
  nowUs(): number;
  /** Lets `ms` of the robot's time pass before a call (the latency knob). */
  delay(ms: number): Promise<void>;
  /** Whether the robot's e-stop is latched. */
  emergencyStopped(): boolean;
}
