/**
 * Runs a device's commands one at a time, in arrival order, except the priority lane: a task
 * run with `priority` starts at once, ahead of (and beside) whatever is queued or running. That
 * is how an e-stop reaches the robot while a long move is in progress.
 */
export class CommandQueue {
  #tail: Promise<unknown> = Promise.resolve();
  #pending = 0;

  /** How many queued tasks have not finished. */
  get pending(): number {
    return this.#pending;
  }

  run<T>(task: () => Promise<T>, priority = false): Promise<T> {
    if (priority) return task();
    this.#pending += 1;
    const next = this.#tail.then(task, task);
    this.#tail = next.then(
      () => undefined,
      () => undefined,
    );
    return next.finally(() => {
      this.#pending -= 1;
    });
  }
}
