import { describe, expect, it } from 'vitest';
import { FrameSchedule } from './frame-schedule.js';

/** Runs `schedule` over animation frames every `stepMs` from 0 to `untilMs`, the scene changing on each. */
function drawnTimes(schedule: FrameSchedule, stepMs: number, untilMs: number): number[] {
  const drawn: number[] = [];
  for (let now = 0; now <= untilMs; now += stepMs) {
    if (schedule.next(now, false, `scene at ${now}`).view) drawn.push(now);
  }
  return drawn;
}

describe('FrameSchedule', () => {
  it('draws a changing scene on every animation frame when it has no frame interval', () => {
    const schedule = new FrameSchedule({ minIntervalMs: 0, idleRedrawMs: 1000 });
    expect(drawnTimes(schedule, 16, 160)).toHaveLength(11);
    expect(schedule.framesDrawn).toBe(11);
  });

  it('draws a changing scene at most once per frame interval, on the first frame due', () => {
    const schedule = new FrameSchedule({ minIntervalMs: 200, idleRedrawMs: 1000 });
    // 60 frames a second for one second: frames at 0, then the first at or after each 200 ms.
    expect(drawnTimes(schedule, 16, 1000)).toEqual([0, 208, 416, 624, 832]);
  });

  it('keeps a change that came within the interval and draws it when the frame is due', () => {
    const schedule = new FrameSchedule({ minIntervalMs: 200, idleRedrawMs: 1000 });
    expect(schedule.next(0, false, 'a')).toEqual({ view: true, scene: true });
    expect(schedule.next(50, false, 'b')).toEqual({ view: false, scene: false });
    expect(schedule.next(150, true, 'b')).toEqual({ view: false, scene: false });
    // Nothing changed since 50 ms, but b was never drawn, nor the moved view.
    expect(schedule.next(210, false, 'b')).toEqual({ view: true, scene: true });
    expect(schedule.next(420, false, 'b')).toEqual({ view: false, scene: false });
  });

  it('draws only the view when the view moved and the scene did not', () => {
    const schedule = new FrameSchedule({ minIntervalMs: 0, idleRedrawMs: 1000 });
    schedule.next(0, false, 'a');
    expect(schedule.next(16, true, 'a')).toEqual({ view: true, scene: false });
    expect(schedule.next(32, false, 'a')).toEqual({ view: false, scene: false });
  });

  it('counts a frame drawn out of turn (on a resize) and keeps the frames due as they were', () => {
    const schedule = new FrameSchedule({ minIntervalMs: 200, idleRedrawMs: 1000 });
    expect(schedule.next(0, false, 'a').view).toBe(true);
    schedule.drewOutOfTurn();
    expect(schedule.framesDrawn).toBe(2);
    expect(schedule.next(100, true, 'a').view).toBe(false);
    expect(schedule.next(200, true, 'a').view).toBe(true);
    expect(schedule.framesDrawn).toBe(3);
  });

  it('draws a still scene once per idle interval', () => {
    const schedule = new FrameSchedule({ minIntervalMs: 200, idleRedrawMs: 1000 });
    const drawn: number[] = [];
    for (let now = 0; now <= 3000; now += 16) {
      if (schedule.next(now, false, 'still').scene) drawn.push(now);
    }
    expect(drawn).toEqual([0, 1008, 2016]);
  });
});
