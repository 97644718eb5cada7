import { availableParallelism } from 'node:os';

/**
 * The local model's default CPU threads: one fewer than the cores, at least 1 and at most 4. The
 * core left is the robot's (its HAL and heartbeat run in this process or beside it), and
 * llama.cpp's threads spin while they wait, so a model on every core starves the rest: on a
 * busy 2-core machine one thread answered about 3x sooner than two.
 */
export function defaultThreads(cores: number = availableParallelism()): number {
  return Math.max(1, Math.min(4, cores - 1));
}
