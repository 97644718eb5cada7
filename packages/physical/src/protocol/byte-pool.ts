/** How many bytes each slab of a {@link BytePool} holds by default. */
export const DEFAULT_SLAB_BYTES = 64 * 1024;

/**
 * Hands out byte arrays as views of a shared slab, as Node's Buffer pool does, but in any
 * JavaScript runtime: every `new Uint8Array(n)` (and `TextEncoder.encode`, `slice`) allocates an
 * ArrayBuffer of its own, which costs several times more than writing a short message, while a
 * view of an existing one costs next to nothing.
 *
 * Bytes once taken are never written again: the pool only moves forward, and a full slab is
 * replaced by a new one (the old one lives on as long as a view of it does). So a request's bytes
 * stay exactly as sent for as long as a transport holds them to resend.
 */
export class BytePool {
  readonly #slabBytes: number;
  #slab: Uint8Array;
  #used = 0;

  constructor(slabBytes = DEFAULT_SLAB_BYTES) {
    this.#slabBytes = slabBytes;
    this.#slab = new Uint8Array(slabBytes);
  }

  /**
   * Writable room for at least `bytes` bytes at the pool's front. Write into it, then
   * {@link take} what was written; anything not taken is handed out again by the next call.
   */
  room(bytes: number): Uint8Array {
    if (this.#slab.length - this.#used < bytes) {
      this.#slab = new Uint8Array(Math.max(this.#slabBytes, bytes));
      this.#used = 0;
    }
    return this.#slab.subarray(this.#used);
  }

  /** The first `bytes` bytes of the last {@link room}, now the caller's for good. */
  take(bytes: number): Uint8Array {
    const view = this.#slab.subarray(this.#used, this.#used + bytes);
    this.#used += bytes;
    return view;
  }
}
