// toolBackedHal: a HAL whose calls are tool calls. Every asynchronous call of the call table goes
// through the executor (counted, leashed), the e-stop and synchronous state stay on the robot.
import { SimulationHAL } from '@hal/simulation';
import { HAL_CALL_TABLE } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { createToolExecutor } from './executor.js';
import type { ToolCall } from './executor.js';
import { halTools } from './tools.js';
import { toolBackedHal } from './tool-backed-hal.js';

let sim: SimulationHAL | undefined;
afterEach(async () => {
  await sim?.cleanup();
  sim = undefined;
});

async function backed(options: { include?: string[]; geofence?: boolean } = {}) {
  sim = new SimulationHAL();
  await sim.initialize();
  const executor = createToolExecutor(sim, {
    tools: halTools(sim, options.include === undefined ? {} : { include: options.include }),
    ...(options.geofence === true
      ? { leash: { geofence: { minX: -0.2, maxX: 0.2, minY: -0.2, maxY: 0.2 } } }
      : {}),
  });
  const calls: string[] = [];
  const hal = toolBackedHal(sim, (call: ToolCall) => {
    calls.push(call.name);
    return executor.execute(call);
  });
  return { sim, hal, calls };
}

describe('toolBackedHal', () => {
  it('sends motions and reads through the tools, with their arguments by name', async () => {
    const { hal, calls, sim } = await backed();
    expect((await hal.locomotion.moveForward(10)).success).toBe(true);
    expect((await hal.locomotion.rotate('left', 90)).success).toBe(true);
    expect((await hal.locomotion.drive(0.2, 0.2, 200)).success).toBe(true);
    const pose = await hal.locomotion.getPose();
    expect(pose.position.x).toBeCloseTo(sim.robot.x, 6);
    const imu = await hal.vision.getIMU();
    expect(imu.heading).toBeCloseTo(sim.robot.yaw, 1);
    expect(await hal.vision.captureFrame()).toMatch(/^data:image\/jpeg;base64,/);
    expect(calls).toEqual([
      'move_forward',
      'rotate',
      'drive',
      'get_pose',
      'get_imu',
      'capture_frame',
    ]);
  });

  it('answers a leash refusal as a failed result that keeps the refusal code', async () => {
    const { hal, sim } = await backed({ geofence: true });
    const result = await hal.locomotion.moveForward(50);
    expect(result.success).toBe(false);
    expect(result.details?.['code']).toBe('LEASH_GEOFENCE');
    expect(sim.robot.x).toBe(0);
  });

  it('refuses a call the tools do not offer: a motion fails, a read rejects', async () => {
    const { hal, sim } = await backed({ include: ['move_forward', 'get_pose'] });
    const turned = await hal.locomotion.rotate('left', 90);
    expect(turned.success).toBe(false);
    expect(turned.details?.['code']).toBe('UNKNOWN_TOOL');
    await expect(hal.vision.getIMU()).rejects.toMatchObject({ code: 'NOT_IMPLEMENTED' });
    expect(sim.robot.yaw).toBe(0);
  });

  it('keeps the e-stop and synchronous state on the robot, the reset through the tools', async () => {
    const { hal, calls, sim } = await backed({ include: ['get_pose'] });
    expect((await hal.safety.emergencyStop('test')).success).toBe(true);
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect(hal.safety.getSafetyStatus().emergencyStopped).toBe(true);
    expect(calls).toEqual([]);
    // the reset is a tool call: not offered here, so refused, and the stop stays engaged
    expect((await hal.safety.resetEmergencyStop()).success).toBe(false);
    expect(calls).toEqual(['reset_emergency_stop']);
    expect(sim.safety.isEmergencyStopped()).toBe(true);
  });

  it('routes every asynchronous call of the call table but the e-stop, and leaves a subsystem the table lacks alone', async () => {
    const { hal, calls } = await backed();
    // what stays on the robot, read from the table: the cached reads, the log and the e-stop
    const kept = HAL_CALL_TABLE.filter(
      (s) => s.cached || s.kind === 'void' || s.tool.safety === 'estop',
    ).map((s) => s.method);
    expect(kept.sort()).toEqual(
      ['emergencyStop', 'getSafetyStatus', 'isEmergencyStopped', 'log'].sort(),
    );
    hal.safety.isEmergencyStopped();
    hal.safety.getSafetyStatus();
    hal.communication.log('kept on the robot', 'info');
    expect(calls).toEqual([]);
    await hal.safety.resetEmergencyStop();
    await hal.locomotion.stop();
    expect(calls).toEqual(['reset_emergency_stop', 'stop']);
    // the V1 robot has no arm: its HAL has no manipulation, and neither has the tool-backed one
    expect(hal.manipulation).toBeUndefined();
  });
});
