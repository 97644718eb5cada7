// One robot model, two shells: the in-process mock robot (protocol 1.1 over the wire) and the
// simulated robot (in a world) run the same commands through @hal/kinematics' RobotModel, so they
// must end every command with the same steps and the same pose (the heading to the bit, x and y
// to 1e-10 cm, as the simulated robot gives them in metres), and refuse the same commands with
// the same code and message. A rule written again in either shell shows here; the emulator-
// agreement test holds the model itself to the firmware.
import { MockRobot } from '@hal/physical/testing';
import { World } from '@hal/simulation';
import type { SimRobot } from '@hal/simulation';
import { isHalError } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { AGREEMENT_SCRIPT as SCRIPT, commandSimRobot } from './agreement-script.js';
import type { Command } from './agreement-script.js';

/** The same command on the simulated robot; a refusal is returned as its code and message. */
function onSimulation(
  robot: SimRobot,
  command: Command,
): { code: string; message: string } | undefined {
  try {
    commandSimRobot(robot, command);
  } catch (error) {
    if (!isHalError(error)) throw error;
    return { code: error.code, message: error.message };
  }
  return undefined;
}

function mockRig() {
  let nowMs = 0;
  const robot = new MockRobot({ now: () => nowMs });
  const encoder = new TextEncoder();
  const decoder = new TextDecoder();
  let seq = 1;
  let sid = 0;
  const send = (body: Command): Record<string, unknown> => {
    seq += 1;
    const bytes = encoder.encode(JSON.stringify({ ...body, seq, ...(sid === 0 ? {} : { sid }) }));
    return JSON.parse(decoder.decode(robot.handle(bytes))) as Record<string, unknown>;
  };
  sid = Number(send({ cmd: 'hello', nonce: 'agreement' })['sid']);
  return {
    send,
    /** Runs the robot's clock on in 100 ms steps, with a status request each (the host's heartbeat). */
    settle(): Record<string, unknown> {
      for (let i = 0; i < 10_000; i += 1) {
        const status = send({ cmd: 'get_status' });
        if (status['running'] === false) return status;
        nowMs += 100;
      }
      throw new Error('the mock robot never finished its motion');
    },
  };
}

describe('the mock robot and the simulated robot', () => {
  it('end every command of the script with the same steps and the same pose', () => {
    const mock = mockRig();
    const world = new World({ map: { name: 'open', arena: { width: 20, height: 20 } } });
    const sim = world.addRobot();
    for (const command of SCRIPT) {
      const where = JSON.stringify(command);
      expect(mock.send(command)['ok'], where).toBe(true);
      const status = mock.settle();
      expect(onSimulation(sim, command), where).toBeUndefined();
      if (!world.advanceUntil(() => !sim.running, 120_000_000)) throw new Error('never finished');
      expect(status['move_outcome'], where).toBe('done');
      expect(sim.motion?.outcome, where).toBe('done');
      expect([status['left_steps'], status['right_steps']], where).toEqual([
        sim.leftSteps,
        sim.rightSteps,
      ]);
      // the same odometry bits; the simulated robot only says them in metres (x / 100 * 100)
      expect(Number(status['x_cm']), where).toBeCloseTo(sim.x * 100, 10);
      expect(Number(status['y_cm']), where).toBeCloseTo(sim.y * 100, 10);
      expect(status['heading_rad'], where).toBe(sim.yaw);
    }
  });

  it('refuse the same commands with the same code and message, latch alike and keep the same carry', () => {
    const mock = mockRig();
    const world = new World({ map: { name: 'open', arena: { width: 20, height: 20 } } });
    const sim = world.addRobot();
    const script: Command[] = [
      { cmd: 'move_cm', left_cm: 10, right_cm: 10 },
      { cmd: 'move_cm', left_cm: 10, right_cm: 200 }, // over the step limit: latches
      { cmd: 'move_steps', left: 10, right: 10 }, // refused while latched
      { cmd: 'reset_estop' },
      { cmd: 'move_steps', left: 10, right: 10, speed: 0 }, // no speed
      { cmd: 'rotate_deg', degrees: 40_000 }, // over the step limit, named by its field
      { cmd: 'reset_estop' },
      { cmd: 'drive', left_sps: 100, right_sps: 100, duration_ms: 600_001 },
      { cmd: 'move_cm', left_cm: 10, right_cm: 10 }, // the carry survived the refusals
    ];
    for (const command of script) {
      const where = JSON.stringify(command);
      const reply = mock.send(command);
      const simRefusal = onSimulation(sim, command);
      const error = reply['error'] as { code: string; message: string } | undefined;
      expect(
        error === undefined ? undefined : { code: error.code, message: error.message },
        where,
      ).toEqual(simRefusal);
      const status = mock.settle();
      world.advanceUntil(() => !sim.running, 120_000_000);
      const safety = status['safety'] as Record<string, unknown>;
      expect([safety['estop'], safety['estop_reason'], safety['trips']], where).toEqual([
        sim.emergencyStopped,
        sim.emergencyStopReason,
        sim.trips,
      ]);
      expect([status['left_steps'], status['right_steps']], where).toEqual([
        sim.leftSteps,
        sim.rightSteps,
      ]);
    }
    expect(sim.trips).toBe(2);
  });
});
