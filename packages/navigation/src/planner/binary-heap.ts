/**
 * An indexed min-heap of grid nodes on typed arrays, ordered by f and, between equal f, by larger
 * g (the node nearer the goal first, which keeps A* from expanding whole plateaus of ties). It is
 * a 4-ary heap: half the depth of a binary one, which makes `pop` (the open list's hot spot)
 * cheaper. Each node is in the heap at most once: a better route to a queued node lowers its key
 * in place (`decrease`). Node ids are 0..capacity-1.
 */
export class NodeHeap {
  readonly #node: Int32Array;
  readonly #f: Float64Array;
  readonly #g: Float64Array;
  readonly #position: Int32Array;
  #size = 0;

  /** @param capacity - the number of distinct nodes (the grid's cell count) */
  constructor(capacity: number) {
    this.#node = new Int32Array(capacity);
    this.#f = new Float64Array(capacity);
    this.#g = new Float64Array(capacity);
    this.#position = new Int32Array(capacity);
  }

  get size(): number {
    return this.#size;
  }

  clear(): void {
    this.#size = 0;
  }

  /** Queues a node that is not in the heap. */
  push(node: number, f: number, g: number): void {
    const i = this.#size;
    this.#size += 1;
    this.#siftUp(i, node, f, g);
  }

  /** Lowers the key of a node that is in the heap. */
  decrease(node: number, f: number, g: number): void {
    this.#siftUp(this.#position[node] as number, node, f, g);
  }

  /** Removes the node with the smallest key and returns it (call only when size > 0). */
  pop(): number {
    const nodes = this.#node;
    const fs = this.#f;
    const gs = this.#g;
    const pos = this.#position;
    const top = nodes[0] as number;
    this.#size -= 1;
    const n = this.#size;
    if (n === 0) return top;
    const node = nodes[n] as number;
    const f = fs[n] as number;
    const g = gs[n] as number;
    let i = 0;
    for (;;) {
      const first = 4 * i + 1;
      if (first >= n) break;
      // The smallest of up to four children.
      let best = first;
      let bf = fs[first] as number;
      let bg = gs[first] as number;
      const last = first + 4 < n ? first + 4 : n;
      for (let c = first + 1; c < last; c += 1) {
        const cf = fs[c] as number;
        if (cf < bf || (cf === bf && (gs[c] as number) > bg)) {
          best = c;
          bf = cf;
          bg = gs[c] as number;
        }
      }
      if (f < bf || (f === bf && g >= bg)) break;
      const moved = nodes[best] as number;
      nodes[i] = moved;
      fs[i] = bf;
      gs[i] = bg;
      pos[moved] = i;
      i = best;
    }
    nodes[i] = node;
    fs[i] = f;
    gs[i] = g;
    pos[node] = i;
    return top;
  }

  #siftUp(start: number, node: number, f: number, g: number): void {
    const nodes = this.#node;
    const fs = this.#f;
    const gs = this.#g;
    const pos = this.#position;
    let i = start;
    while (i > 0) {
      const parent = (i - 1) >> 2;
      const pf = fs[parent] as number;
      if (pf < f || (pf === f && (gs[parent] as number) >= g)) break;
      const moved = nodes[parent] as number;
      nodes[i] = moved;
      fs[i] = pf;
      gs[i] = gs[parent] as number;
      pos[moved] = i;
      i = parent;
    }
    nodes[i] = node;
    fs[i] = f;
    gs[i] = g;
    pos[node] = i;
  }
}
