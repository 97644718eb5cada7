// An e-stop NatsHAL takes while it is not connected (before initialize(), after cleanup()): it
// latches on the host at once, answers success with `delivered: false`, and the next
// initialize() latches the device itself before reporting ready.
import { NatsHAL, serveHalOnNats } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { sanitizeEstopReason } from '@hal/types';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';

const cleanups: Array<() => Promise<void>> = [];
afterEach(async () => {
  for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
});
afterAll(async () => {
  await stopAllNatsServers();
});

async function served(deviceId: string) {
  const server = await startNatsServer();
  const device = new SimulationHAL();
  await device.initialize();
  const gateway = await serveHalOnNats(device, { servers: server.url, deviceId });
  cleanups.push(async () => {
    await gateway.close();
    await device.cleanup();
  });
  const hal = new NatsHAL({ servers: server.url, deviceId });
  cleanups.push(() => hal.cleanup());
  return { device, hal };
}

describe('an e-stop while NatsHAL is not connected', () => {
  it('latches the host, and initialize() latches the device before ready', async () => {
    const { device, hal } = await served('estop-early');
    const reason = '\u0007bumper\r\nhit';
    const result = await hal.safety.emergencyStop(reason);
    expect(result.success).toBe(true);
    expect(result.data).toMatchObject({ delivered: false, reason: sanitizeEstopReason(reason) });
    expect(hal.safety.getSafetyStatus()).toMatchObject({
      emergencyStopped: true,
      emergencyStopReason: 'bumper hit',
    });
    expect(device.safety.isEmergencyStopped()).toBe(false);

    await hal.initialize();
    expect(device.safety.isEmergencyStopped()).toBe(true);
    expect(device.safety.getSafetyStatus().emergencyStopReason).toBe('bumper hit');
    expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');

    expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
    expect(hal.safety.isEmergencyStopped()).toBe(false);
    expect(device.safety.isEmergencyStopped()).toBe(false);
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
  });

  it('after cleanup(): the latch holds, the reset needs the connection', async () => {
    const { device, hal } = await served('estop-late');
    await hal.initialize();
    await hal.cleanup();
    const result = await hal.safety.emergencyStop(undefined);
    expect(result).toMatchObject({ success: true, data: { delivered: false } });
    expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe(sanitizeEstopReason(undefined));
    expect((await hal.safety.resetEmergencyStop()).code).toBe('NOT_READY');
    expect(hal.safety.isEmergencyStopped()).toBe(true);

    await hal.initialize();
    expect(device.safety.isEmergencyStopped()).toBe(true);
    expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
  });

  it('a connected e-stop reports the reason the device stored, delivered', async () => {
    const { hal } = await served('estop-connected');
    await hal.initialize();
    const result = await hal.safety.emergencyStop(42 as unknown as string);
    expect(result).toMatchObject({ success: true, data: { delivered: true, reason: '42' } });
    expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('42');
  });
});
