import { describe, expect, it } from 'vitest';
import { MockRobot } from './mock-robot.js';

const encode = (value: unknown) => new TextEncoder().encode(JSON.stringify(value));
const decode = (bytes: Uint8Array | undefined) =>
  bytes === undefined
    ? undefined
    : (JSON.parse(new TextDecoder().decode(bytes)) as Record<string, unknown>);

function openSession(robot: MockRobot): number {
  const hello = decode(robot.handle(encode({ cmd: 'hello', seq: 1, nonce: 'n' })))!;
  return hello['sid'] as number;
}

describe('MockRobot', () => {
  describe('#dropReplies', () => {
    it('executes the request but loses its reply; the retry is answered from memory', () => {
      let now = 0;
      const robot = new MockRobot({ now: () => now });
      const sid = openSession(robot);
      const move = encode({ cmd: 'move_steps', seq: 2, sid, left: 100, right: 100 });
      robot.dropReplies(1);
      expect(robot.receive(move)).toBeUndefined();
      const retry = decode(robot.receive(move))!;
      expect(retry).toMatchObject({ ok: true, move_id: 1, left_steps: 100 });
      expect(robot.motionsStarted).toBe(1);
      now += 10_000;
      expect(robot.position).toEqual({ left: 100, right: 100 });
    });
  });

  describe('#unresponsive', () => {
    it('neither executes nor answers anything', () => {
      const robot = new MockRobot();
      robot.unresponsive = true;
      expect(robot.receive(encode({ cmd: 'estop' }))).toBeUndefined();
      expect(robot.estopped).toBe(false);
      expect(robot.requests).toEqual([]);
    });
  });

  describe('#restart', () => {
    it('forgets the session and the e-stop and counts steps from zero again', () => {
      let now = 0;
      const robot = new MockRobot({ now: () => now });
      const sid = openSession(robot);
      robot.handle(encode({ cmd: 'move_steps', seq: 2, sid, left: 50, right: 50 }));
      robot.handle(encode({ cmd: 'estop' }));
      now += 1000;
      robot.restart();
      expect(robot.estopped).toBe(false);
      expect(robot.position).toEqual({ left: 0, right: 0 });
      const refused = decode(robot.handle(encode({ cmd: 'heartbeat', seq: 3, sid })))!;
      expect(refused['error']).toMatchObject({ code: 'SESSION_MISMATCH' });
      expect(robot.lastRequest).toEqual({ cmd: 'heartbeat', seq: 3, sid });
    });
  });

  describe('host timeout', () => {
    it('stops a drive when no request arrives for the host timeout', () => {
      let now = 0;
      const robot = new MockRobot({ now: () => now, hostTimeoutMs: 1000 });
      const sid = openSession(robot);
      robot.handle(encode({ cmd: 'drive', seq: 2, sid, left_sps: 500, right_sps: 500 }));
      now += 5000;
      const stopped = robot.position.left;
      const status = decode(robot.handle(encode({ cmd: 'get_status', seq: 3, sid })))!;
      expect(status).toMatchObject({ running: false, move_outcome: 'host_timeout' });
      expect(status['safety']).toMatchObject({ last_trip: { reason: 'host_timeout' } });
      expect(robot.position.left).toBe(stopped);
    });
  });
});
