// CONTRIBUTING.md, "Add a transport", done once: a TransportFactory of our own (an in-memory
// pipe to the mock robot, written as a new link would be: the request/reply half is the shared
// ReplyMatcher, the bytes go through the real codec) given to PhysicalHAL, which drives the
// robot through it: the hello, a motion, a lost reply resent exactly once, and close.
import { describe, expect, it } from 'vitest';
import { PhysicalHAL } from '@hal/physical';
import type { Transport, TransportFactory } from '@hal/physical';
import { ReplyMatcher } from '@hal/physical/protocol';
import { MockRobot } from '@hal/physical/testing';
import { HalError } from '@hal/types';

// the mock robot's clock runs 50 times faster: its 10 s host timeout is 200 ms of real time
const TIME_SCALE = 50;

/** What the pipe carried, for the test to look at. */
interface PipeLog {
  requests: number;
  bytesSent: number;
  closed: boolean;
}

/**
 * A transport to `robot` over an in-memory pipe: each request's bytes reach the robot on the next
 * macrotask, and its reply (if the robot sends one) comes back through `context.decode`.
 */
function pipeTransport(
  robot: MockRobot,
  log: PipeLog,
  replyTimeoutMs: number,
): TransportFactory<'pipe'> {
  return {
    type: 'pipe',
    connect: async (context): Promise<Transport> => {
      const matcher = new ReplyMatcher();
      let closed = false;
      return {
        type: 'pipe',
        request: (seq, bytes, options) =>
          matcher.request(
            seq,
            async () => {
              if (closed) throw new HalError('NOT_CONNECTED', 'the pipe is closed');
              log.requests += 1;
              log.bytesSent += bytes.length;
              const copy = bytes.slice();
              setTimeout(() => {
                if (closed) return;
                const reply = robot.receive(copy);
                if (reply !== undefined) matcher.deliver(context.decode(reply));
              }, 0);
            },
            { timeoutMs: replyTimeoutMs, ...options },
          ),
        stats: () => matcher.stats(),
        close: async () => {
          closed = true;
          log.closed = true;
          matcher.close();
        },
      };
    },
  };
}

describe('a transport of our own (CONTRIBUTING.md: Add a transport)', () => {
  it('carries the session, a motion and a resent request between PhysicalHAL and the robot', async () => {
    const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
    const log: PipeLog = { requests: 0, bytesSent: 0, closed: false };
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-pipe' },
      { transport: pipeTransport(robot, log, 100), timeScale: TIME_SCALE },
    );
    try {
      await hal.initialize();
      expect(robot.requests[0]).toMatchObject({ cmd: 'hello' });
      // PhysicalHAL reads the link's statistics from the transport: what our pipe counted
      expect(hal.transportStats()).toMatchObject({ sent: log.requests, retries: 0 });

      expect(await hal.locomotion.moveForward(2)).toMatchObject({ success: true });
      expect(robot.requests.some((r) => r['cmd'] === 'move_cm')).toBe(true);
      expect(robot.motionsStarted).toBe(1);

      // a lost reply: the matcher resends the same bytes and the robot runs the motion once
      robot.dropReplies(1);
      expect(await hal.locomotion.moveForward(2)).toMatchObject({ success: true });
      expect(robot.motionsStarted).toBe(2);
      expect(hal.transportStats()?.retries).toBeGreaterThanOrEqual(1);
      expect(log.requests).toBeGreaterThan(robot.motionsStarted);
      expect(log.bytesSent).toBeGreaterThan(0);
    } finally {
      await hal.cleanup();
    }
    expect(log.closed).toBe(true);
  });

  it('refuses to initialize (NOT_CONNECTED) over a pipe the robot never answers', async () => {
    const robot = new MockRobot({ timeScale: TIME_SCALE });
    robot.unresponsive = true;
    const log: PipeLog = { requests: 0, bytesSent: 0, closed: false };
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-silent' },
      { transport: pipeTransport(robot, log, 20), timeScale: TIME_SCALE },
    );
    try {
      await expect(hal.initialize()).rejects.toMatchObject({ code: 'NOT_CONNECTED' });
      expect(log.requests).toBeGreaterThan(0);
      expect(robot.requests).toHaveLength(0);
    } finally {
      await hal.cleanup();
    }
  });
});
