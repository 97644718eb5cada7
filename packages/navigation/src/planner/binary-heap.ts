/**
 * An indexed min-heap of grid nodes keyed by one number, on typed arrays. It is a 4-ary heap:
 * half the depth of a binary one, which makes `pop` (the open list's hot spot) cheaper. Each
 * node is in the heap at most once: a better route to a queued node lowers its key in place
 * (`decrease`). Node ids are 0..capacity-1.
 */
export class NodeHeap {
  readonly #node: Int32Array;
  readonly #key: Float64Array;
  readonly #position: Int32Array;
  #size = 0;

  /** @param capacity - the number of distinct nodes (the grid's cell count) */
  constructor(capacity: number) {
    this.#node = new Int32Array(capacity);
    this.#key = new Float64Array(capacity);
    this.#position = new Int32Array(capacity);
  }

  get size(): number {
    return this.#size;
  }

  clear(): void {
    this.#size = 0;
  }

  /** Queues a node that is not in the heap. */
  push(node: number, key: number): void {
    const i = this.#size;
    this.#size += 1;
    this.#siftUp(i, node, key);
  }

  /** Lowers the key of a node that is in the heap. */
  decrease(node: number, key: number): void {
    this.#siftUp(this.#position[node] as number, node, key);
  }

  /** Removes the node with the smallest key and returns it (call only when size > 0). */
  pop(): number {
    const nodes = this.#node;
    const keys = this.#key;
    const pos = this.#position;
    const top = nodes[0] as number;
    this.#size -= 1;
    const n = this.#size;
    if (n === 0) return top;
    const node = nodes[n] as number;
    const key = keys[n] as number;
    let i = 0;
    for (;;) {
      const first = 4 * i + 1;
      if (first >= n) break;
      // The smallest of up to four children.
      let best = first;
      let bestKey = keys[first] as number;
      const last = first + 4 < n ? first + 4 : n;
      for (let c = first + 1; c < last; c += 1) {
        const k = keys[c] as number;
        if (k < bestKey) {
          best = c;
          bestKey = k;
        }
      }
      if (key <= bestKey) break;
      const moved = nodes[best] as number;
      nodes[i] = moved;
      keys[i] = bestKey;
      pos[moved] = i;
      i = best;
    }
    nodes[i] = node;
    keys[i] = key;
    pos[node] = i;
    return top;
  }

  #siftUp(start: number, node: number, key: number): void {
    const nodes = this.#node;
    const keys = this.#key;
    const pos = this.#position;
    let i = start;
    while (i > 0) {
      const parent = (i - 1) >> 2;
      const parentKey = keys[parent] as number;
      if (parentKey <= key) break;
      const moved = nodes[parent] as number;
      nodes[i] = moved;
      keys[i] = parentKey;
      pos[moved] = i;
      i = parent;
    }
    nodes[i] = node;
    keys[i] = key;
    pos[node] = i;
  }
}
