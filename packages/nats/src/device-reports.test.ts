import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { announcementOf, cameraFrameOf, healthOf } from './device-reports.js';
import { HealthSchema } from './messages.js';

const context = { uptimeS: 12.5, cpuPercent: 3, includeDiagnostics: false };

describe('what a served device reports of itself', () => {
  it('says not_ready, healthy, emergency_stopped and degraded as the HAL stands', async () => {
    const hal = new SimulationHAL();
    expect(healthOf(hal, context).status).toBe('not_ready');
    await hal.initialize();
    const healthy = healthOf(hal, context);
    expect(HealthSchema.parse(healthy)).toMatchObject({
      status: 'healthy',
      uptime_s: 12.5,
      cpu_percent: 3,
      mode: 'simulation',
    });
    expect(healthy.diagnostics).toBeUndefined();
    await hal.safety.emergencyStop('test');
    expect(healthOf(hal, context).status).toBe('emergency_stopped');
    await hal.safety.resetEmergencyStop();
    const status = hal.safety.getSafetyStatus();
    hal.safety.getSafetyStatus = () => ({ ...status, errors: ['left motor stalled'] });
    const degraded = healthOf(hal, { ...context, includeDiagnostics: true });
    expect(degraded.status).toBe('degraded');
    expect(degraded.diagnostics?.errors).toEqual(['left motor stalled']);
    await hal.cleanup();
  });

  it("gives a JPEG frame with the JPEG's own size, and refuses a frame that is not one", async () => {
    const hal = new SimulationHAL();
    await hal.initialize();
    const frame = await cameraFrameOf(hal);
    expect(frame.format).toBe('jpeg');
    expect(frame.width).toBeGreaterThan(0);
    expect(frame.height).toBeGreaterThan(0);
    expect(Buffer.from(frame.data, 'base64').subarray(0, 2)).toEqual(Buffer.from([0xff, 0xd8]));
    hal.vision.captureFrame = async () =>
      `data:image/png;base64,${Buffer.from('png').toString('base64')}`;
    await expect(cameraFrameOf(hal)).rejects.toMatchObject({ code: 'HARDWARE_ERROR' });
    await hal.cleanup();
  }, 30_000);

  it('announces the type, mode, capabilities and state rate', () => {
    const hal = new SimulationHAL();
    const info = hal.getDeviceInfo();
    expect(announcementOf(hal, 20)).toEqual({
      device_type: info.type,
      mode: info.mode,
      caps: info.capabilities,
      state_rate_hz: 20,
    });
  });
});
