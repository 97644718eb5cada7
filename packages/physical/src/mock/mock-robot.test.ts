import { describe, expect, it } from 'vitest';
import { createAuthenticator } from '../protocol/auth.js';
import { MessageCodec } from '../protocol/codec.js';
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
  describe('authentication', () => {
    it('without a key runs as the unauthenticated opt-out: hello says auth none, seed-style requests run', () => {
      let now = 0;
      const robot = new MockRobot({ now: () => now });
      const hello = decode(robot.handle(encode({ cmd: 'hello', seq: 1, nonce: 'n' })))!;
      expect(hello).toMatchObject({ ok: true, auth: 'none', protocol_version: '1.1' });
      const move = decode(robot.handle(encode({ cmd: 'move_steps', left: 40, right: 40 })))!;
      expect(move).toMatchObject({ ok: true, move_id: 1 });
      expect(move).not.toHaveProperty('seq');
      now += 10_000;
      expect(robot.position).toEqual({ left: 40, right: 40 });
    });

    it('with a key says auth hmac-sha256 and refuses seed-style requests and an unsessioned reset', async () => {
      const auth = await createAuthenticator('00112233');
      const codec = new MessageCodec(auth);
      const robot = new MockRobot({ auth });
      const send = (request: Record<string, unknown>) => {
        const result = codec.decode(robot.handle(codec.encode(request)));
        if (!result.ok) throw result.error;
        return result.reply;
      };
      const hello = send({ cmd: 'hello', seq: 1, nonce: 'n' });
      expect(hello).toMatchObject({ ok: true, auth: 'hmac-sha256' });
      const sid = hello.sid!;
      expect(send({ cmd: 'move_steps', left: 40, right: 40 }).error?.code).toBe('AUTH_FAILED');
      expect(robot.motionsStarted).toBe(0);
      expect(send({ cmd: 'estop', seq: 2, sid }).ok).toBe(true);
      expect(send({ cmd: 'reset_estop' }).error?.code).toBe('AUTH_FAILED');
      expect(send({ cmd: 'reset_estop', seq: 3, sid: sid + 1 }).error?.code).toBe(
        'SESSION_MISMATCH',
      );
      expect(robot.estopped).toBe(true);
      expect(send({ cmd: 'reset_estop', seq: 4, sid }).ok).toBe(true);
      expect(robot.estopped).toBe(false);
    });

    it('refuses a request whose MAC differs in one digit', async () => {
      const auth = await createAuthenticator('00112233');
      const robot = new MockRobot({ auth });
      const json = '{"cmd":"hello","seq":1,"nonce":"n"}';
      const mac = auth.mac(encode(JSON.parse(json)));
      const forged = `${json}#${mac[0] === '0' ? '1' : '0'}${mac.slice(1)}`;
      const reply = new TextDecoder().decode(robot.handle(new TextEncoder().encode(forged)));
      expect(reply).toContain('"AUTH_FAILED"');
      expect(robot.requests).toEqual([]);
    });
  });

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
  describe('the firmware rules (the robot model SimRobot uses too)', () => {
    it('refuses a move_cm over the step limit before committing its distance: the e-stop latches and the carry is kept', () => {
      let now = 0;
      const robot = new MockRobot({ now: () => now, hostTimeoutMs: 10_000 });
      const sid = openSession(robot);
      let seq = 1;
      const send = (request: Record<string, unknown>) =>
        decode(robot.handle(encode({ ...request, seq: (seq += 1), sid })))!;
      expect(send({ cmd: 'move_cm', left_cm: 10, right_cm: 10 })).toMatchObject({
        left_steps: 2172,
      });
      now += 5000; // the move is over (about 3.1 s)
      const refused = send({ cmd: 'move_cm', left_cm: 10, right_cm: 200 });
      expect(refused['error']).toMatchObject({
        code: 'RANGE_EXCEEDED',
        message:
          '"right_cm" gives 43460 steps; the limit is 40960 steps per command (emergency stop latched)',
        details: { field: 'right_cm', value: 43460, estop: true },
      });
      const status = send({ cmd: 'get_status' });
      expect(status['safety']).toMatchObject({
        estop: true,
        estop_reason: 'step limit: "right_cm" 43460 steps',
        trips: 1,
        last_trip: { reason: 'step_limit' },
      });
      expect(send({ cmd: 'reset_estop' })).toMatchObject({ ok: true, was_estopped: true });
      // the 0.99 step carried by the first move is still there: the refused one added nothing
      expect(send({ cmd: 'move_cm', left_cm: 10, right_cm: 10 })).toMatchObject({
        left_steps: 2173,
      });
    });

    it('refuses a set_config value outside the firmware range by its wire name and changes nothing', () => {
      const robot = new MockRobot();
      const sid = openSession(robot);
      const refused = decode(
        robot.handle(
          encode({ cmd: 'set_config', seq: 2, sid, wheel_base_cm: 12, host_timeout_ms: 100 }),
        ),
      )!;
      expect(refused['error']).toMatchObject({
        code: 'RANGE_EXCEEDED',
        details: { field: 'host_timeout_ms', min: 500, max: 10_000, value: 100 },
      });
      const status = decode(robot.handle(encode({ cmd: 'get_status', seq: 3, sid })))!;
      expect(status['safety']).toMatchObject({ host_timeout_ms: 2000 });
      const hello = decode(robot.handle(encode({ cmd: 'hello', seq: 4, nonce: 'm' })))!;
      expect(hello['config']).toMatchObject({ wheel_base_cm: 10, host_timeout_ms: 2000 });
    });
  });
});
