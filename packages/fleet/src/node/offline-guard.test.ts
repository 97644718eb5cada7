import { describe, expect, it } from 'vitest';
import { z } from 'zod';
import { SimulationHAL } from '@hal/simulation';
import { HAL_CALL_TABLE, successResult } from '@hal/types';
import type { CallSpec, HALToolResult } from '@hal/types';
import { OfflineGuardHAL } from './offline-guard.js';

const BEEP: CallSpec = {
  name: 'beep',
  subsystem: 'communication',
  method: 'beep',
  kind: 'result',
  lane: 'queue',
  controllerOnly: true,
  cached: false,
  params: ['times'],
  paramsSchema: () => z.object({ times: z.number() }),
  data: z.looseObject({}),
  tool: { name: 'beep', summary: 'Beep.' },
};

describe('OfflineGuardHAL', () => {
  it('guards a call of an extended table: passed through online, NOT_CONNECTED offline', async () => {
    const inner = new SimulationHAL();
    const beeps: number[] = [];
    Object.assign(inner.communication, {
      beep: (times: number) => {
        beeps.push(times);
        return Promise.resolve(successResult(inner.mode, Date.now()));
      },
    });
    let offline = false;
    const guard = new OfflineGuardHAL(inner, 'cube-1', () => offline, [...HAL_CALL_TABLE, BEEP]);
    const beep = (times: number) =>
      (guard.communication as unknown as { beep(t: number): Promise<HALToolResult> }).beep(times);
    expect(await beep(2)).toMatchObject({ success: true });
    offline = true;
    expect(await beep(3)).toMatchObject({
      success: false,
      code: 'NOT_CONNECTED',
      details: { device: 'cube-1', offline: true },
    });
    expect(beeps).toEqual([2]);
  });

  it('lets the e-stop and the cached safety reads through while offline', async () => {
    const inner = new SimulationHAL();
    await inner.initialize();
    const guard = new OfflineGuardHAL(inner, 'cube-1', () => true);
    expect(await guard.locomotion.moveForward(1)).toMatchObject({ code: 'NOT_CONNECTED' });
    expect(await guard.safety.emergencyStop('offline test')).toMatchObject({ success: true });
    expect(guard.safety.isEmergencyStopped()).toBe(true);
    expect(guard.safety.getSafetyStatus().emergencyStopped).toBe(true);
    await inner.cleanup();
  });
});
