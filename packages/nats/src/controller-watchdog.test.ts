import { describe, expect, it } from 'vitest';
import { ControllerWatchdog } from './controller-watchdog.js';

function clock() {
  let t = 0;
  return { now: () => t, advance: (ms: number) => (t += ms) };
}

describe('ControllerWatchdog', () => {
  it('stops an open-ended drive once its controller has been quiet longer than the timeout', () => {
    const time = clock();
    const expired: string[] = [];
    const dog = new ControllerWatchdog(1000, (c) => expired.push(c), time.now);
    dog.openEnded('agent-1');
    time.advance(900);
    dog.heard('agent-1');
    time.advance(900);
    dog.check();
    expect(expired).toEqual([]);
    dog.heard('someone-else');
    time.advance(200);
    dog.check();
    expect(expired).toEqual(['agent-1']);
    time.advance(5000);
    dog.check();
    expect(expired).toEqual(['agent-1']);
    dog.close();
  });

  it('does nothing once the drive has ended', () => {
    const time = clock();
    const expired: string[] = [];
    const dog = new ControllerWatchdog(1000, (c) => expired.push(c), time.now);
    dog.openEnded('agent-1');
    dog.ended();
    time.advance(5000);
    dog.check();
    expect(expired).toEqual([]);
    dog.close();
  });
});
