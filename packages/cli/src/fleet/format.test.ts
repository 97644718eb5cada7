import { describe, expect, it } from 'vitest';
import type { FleetReport } from '@hal/fleet';
import { fleetErrorText, formatReport } from './format.js';

describe('formatReport', () => {
  it("names the command that resets a latched e-stop, not the library's method", () => {
    const report: FleetReport = {
      mode: 'synchronized',
      success: false,
      results: [
        {
          device: 'sim-a',
          issuedAt: 0,
          result: {
            success: false,
            code: 'EMERGENCY_STOPPED',
            error:
              'moveForward: the emergency stop is latched; call safety.resetEmergencyStop() first',
            timestamp: 0,
            mode: 'simulation',
          },
        },
      ],
      succeeded: [],
      failed: ['sim-a'],
      startedAt: 0,
      executionTime: 3,
    };
    const text = formatReport('forward', report);
    expect(text).toContain(
      'sim-a   FAIL  EMERGENCY_STOPPED: moveForward: the emergency stop is latched; reset it with: hal fleet reset (and the same devices)',
    );
    expect(text).not.toContain('resetEmergencyStop');
  });

  it("rewrites the fleet's own latch hint the same way, and leaves other messages alone", () => {
    expect(fleetErrorText('the fleet e-stop is latched; reset it with resetEmergencyStop()')).toBe(
      'the fleet e-stop is latched; reset it with: hal fleet reset (and the same devices)',
    );
    expect(fleetErrorText('no reply within 2000 ms')).toBe('no reply within 2000 ms');
  });
});
