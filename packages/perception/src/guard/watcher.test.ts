import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { Sight, Sighting } from './sighting.js';
import { Watcher } from './watcher.js';
import type { Trip } from './watcher.js';

const seen = (aheadM: number): Sighting => ({
  aheadM,
  blocked: true,
  atEdge: false,
  source: 'camera',
  at: 0,
});

/** A sight that answers the distances given, one a look, then never again. */
function sightOf(distances: number[]): Sight & { looks: number } {
  const sight = {
    source: 'camera' as const,
    looks: 0,
    look(): Promise<Sighting> {
      const d = distances[sight.looks];
      sight.looks += 1;
      return d === undefined ? new Promise<Sighting>(() => undefined) : Promise.resolve(seen(d));
    },
  };
  return sight;
}

function watch(sight: Sight, trips: Trip[]): Watcher {
  return new Watcher({
    sight,
    periodMs: 100,
    blindLimitMs: 500,
    tooNear: (s) => s.aheadM < 0.1,
    onTrip: (trip) => trips.push(trip),
  });
}

describe('Watcher', () => {
  beforeEach(() => {
    vi.useFakeTimers();
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it('looks once a period and trips once, at the first look that shows something too near', async () => {
    const trips: Trip[] = [];
    const sight = sightOf([0.5, 0.3, 0.08, 0.05]);
    const watcher = watch(sight, trips);
    watcher.start();
    await vi.advanceTimersByTimeAsync(250);
    expect(sight.looks).toBe(3);
    expect(trips).toHaveLength(1);
    expect(trips[0]).toMatchObject({ kind: 'obstacle', sighting: { aheadM: 0.08 } });
    await vi.advanceTimersByTimeAsync(1000);
    expect(sight.looks).toBe(3); // it stopped looking
    expect(trips).toHaveLength(1);
  });

  it('trips blind when no look has come back for its limit', async () => {
    const trips: Trip[] = [];
    const sight = sightOf([0.5]);
    const watcher = watch(sight, trips);
    watcher.start();
    await vi.advanceTimersByTimeAsync(450);
    expect(trips).toHaveLength(0);
    await vi.advanceTimersByTimeAsync(200);
    expect(trips).toEqual([{ kind: 'blind', sinceMs: 500 }]);
  });

  it('counts failed looks as not seeing', async () => {
    const trips: Trip[] = [];
    const failing: Sight = { source: 'range', look: () => Promise.reject(new Error('no reading')) };
    watch(failing, trips).start();
    await vi.advanceTimersByTimeAsync(1000);
    expect(trips).toHaveLength(1);
    expect(trips[0]).toMatchObject({ kind: 'blind' });
  });

  it('trips nothing once stopped', async () => {
    const trips: Trip[] = [];
    const watcher = watch(sightOf([0.5]), trips);
    watcher.start();
    watcher.stop();
    await vi.advanceTimersByTimeAsync(2000);
    expect(trips).toHaveLength(0);
  });
});
