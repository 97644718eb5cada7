/**
 * A min-heap of items by time (ties: by their order of arrival), with the position of each item
 * kept so that its time can be changed or it can be removed in O(log n). The world keeps one
 * entry per robot, at the robot's next event.
 */
export class EventQueue<T> {
  readonly #items: T[] = [];
  readonly #times: number[] = [];
  readonly #orders: number[] = [];
  readonly #index = new Map<T, number>();
  readonly #order = new Map<T, number>();
  #arrivals = 0;

  get size(): number {
    return this.#items.length;
  }

  /** The item due first, or undefined. */
  peek(): T | undefined {
    return this.#items[0];
  }
  /** When the first item is due, or Infinity. */
  peekTime(): number {
    return this.#times[0] ?? Number.POSITIVE_INFINITY;
  }

  /** Adds `item` at `time`, or moves it there if it is queued. */
  set(item: T, time: number): void {
    const at = this.#index.get(item);
    if (at === undefined) {
      this.#order.set(item, this.#arrivals);
      this.#arrivals += 1;
      this.#items.push(item);
      this.#times.push(time);
      this.#orders.push(this.#order.get(item) as number);
      this.#index.set(item, this.#items.length - 1);
      this.#up(this.#items.length - 1);
      return;
    }
    const before = this.#times[at] as number;
    this.#times[at] = time;
    if (time < before) this.#up(at);
    else if (time > before) this.#down(at);
  }

  /** Removes `item` if it is queued. */
  delete(item: T): void {
    const at = this.#index.get(item);
    if (at === undefined) return;
    const last = this.#items.length - 1;
    this.#swap(at, last);
    this.#items.pop();
    this.#times.pop();
    this.#orders.pop();
    this.#index.delete(item);
    this.#order.delete(item);
    if (at < last) {
      this.#up(at);
      this.#down(at);
    }
  }

  /** Every queued item, in no particular order. */
  items(): readonly T[] {
    return this.#items;
  }

  #less(a: number, b: number): boolean {
    const ta = this.#times[a] as number;
    const tb = this.#times[b] as number;
    return ta < tb || (ta === tb && (this.#orders[a] as number) < (this.#orders[b] as number));
  }

  #swap(a: number, b: number): void {
    if (a === b) return;
    const items = this.#items;
    const times = this.#times;
    const orders = this.#orders;
    [items[a], items[b]] = [items[b] as T, items[a] as T];
    [times[a], times[b]] = [times[b] as number, times[a] as number];
    [orders[a], orders[b]] = [orders[b] as number, orders[a] as number];
    this.#index.set(items[a] as T, a);
    this.#index.set(items[b] as T, b);
  }

  #up(i: number): void {
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (!this.#less(i, parent)) return;
      this.#swap(i, parent);
      i = parent;
    }
  }

  #down(i: number): void {
    const n = this.#items.length;
    for (;;) {
      const l = 2 * i + 1;
      const r = l + 1;
      let best = i;
      if (l < n && this.#less(l, best)) best = l;
      if (r < n && this.#less(r, best)) best = r;
      if (best === i) return;
      this.#swap(i, best);
      i = best;
    }
  }
}
