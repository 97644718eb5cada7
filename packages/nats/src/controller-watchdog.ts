/**
 * Stops an open-ended drive whose controller has gone quiet. A drive without a duration keeps
 * the wheels turning until the next command; if the program that started it vanishes (crashed,
 * lost its network), nothing would ever stop it. So the controller must keep talking: any message
 * from it (a command, or NatsHAL's heartbeat) within `timeoutMs`, else `onExpire` stops the robot.
 */
export class ControllerWatchdog {
  #open: { client: string; lastSeen: number } | undefined;
  readonly #timer: NodeJS.Timeout;

  constructor(
    readonly timeoutMs: number,
    readonly onExpire: (client: string) => void,
    readonly now: () => number = Date.now,
  ) {
    this.#timer = setInterval(() => this.check(), Math.max(10, Math.min(250, timeoutMs / 4)));
    this.#timer.unref();
  }

  /** `client` started a drive with no end. */
  openEnded(client: string): void {
    this.#open = { client, lastSeen: this.now() };
  }

  /** The open-ended drive was replaced or stopped. */
  ended(): void {
    this.#open = undefined;
  }

  /** A message came from `client`. */
  heard(client: string): void {
    if (this.#open?.client === client) this.#open.lastSeen = this.now();
  }

  /** Stops the drive if its controller has been quiet too long (run by the timer). */
  check(): void {
    const open = this.#open;
    if (open !== undefined && this.now() - open.lastSeen > this.timeoutMs) {
      this.#open = undefined;
      this.onExpire(open.client);
    }
  }

  close(): void {
    clearInterval(this.#timer);
  }
}
