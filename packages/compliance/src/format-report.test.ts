import { describe, expect, it } from 'vitest';
import { formatReport } from './format-report.js';
import type { ComplianceReport } from './report.js';
import { LATENCY_CLASSES } from './spec.js';

const report: ComplianceReport = {
  aborted: false,
  deviceId: 'cube-01',
  addressed: 'cube-01',
  deviceType: 'v1-stepper-cube',
  mode: 'physical',
  caps: ['locomotion.differential:v1.0'],
  capabilities: ['motor.differential', 'camera'],
  groups: ['format', 'timing', 'errors', 'capability', 'state'],
  judge: 'p50',
  checks: [
    {
      id: 'motor.differential/timing/stop-command',
      capability: 'motor.differential',
      group: 'timing',
      title: 'a stop command round trip',
      status: 'fail',
      reason: 'p50 12.00 ms against the low-latency class (< 10 ms)',
      measured: { samples: 20, p50Ms: 12, p99Ms: 31.4, maxMs: 40 },
      latencyClass: LATENCY_CLASSES.lowLatency,
      durationMs: 300,
    },
    {
      id: 'motor.differential/timing/state-rate',
      capability: 'motor.differential',
      group: 'timing',
      title: 'state streams at 10-100 Hz',
      status: 'pass',
      reason: '19.9 Hz',
      rateHz: 19.93,
      measured: { samples: 39, p50Ms: 50, p99Ms: 52.5, maxMs: 53 },
      durationMs: 2000,
    },
    {
      id: 'camera/timing/frame',
      capability: 'camera',
      group: 'timing',
      title: 'camera.frame.req round trip',
      status: 'skip',
      reason: 'the device does not announce camera',
      durationMs: 0,
    },
  ],
  summary: { passed: 1, failed: 1, skipped: 1 },
  ok: false,
  startedAt: '2026-01-01T00:00:00.000Z',
  durationMs: 2300,
};

describe('formatReport', () => {
  it('prints one row per check with the latencies beside the spec class, reasons under failures and skips', () => {
    const lines = formatReport(report).split('\n');
    expect(lines[0]).toBe('device cube-01 (v1-stepper-cube, physical)');
    expect(lines).toContainEqual(
      expect.stringMatching(
        /^FAIL +motor\.differential +timing +a stop command round trip +p50 12 p99 31 max 40 ms \(n=20\) +low-latency < 10 ms \(p50\)$/,
      ),
    );
    expect(lines).toContainEqual('        p50 12.00 ms against the low-latency class (< 10 ms)');
    expect(lines).toContainEqual(
      expect.stringMatching(/^PASS .* 19\.9 Hz \(interval p99 53 ms\) +10-100 Hz$/),
    );
    expect(lines).toContainEqual('        the device does not announce camera');
    expect(lines.at(-2)).toBe('1 passed, 1 failed, 1 skipped in 2.3 s: NOT COMPLIANT');
  });

  it('says which check groups were left out, beside its verdict', () => {
    const some: ComplianceReport = {
      ...report,
      groups: ['format', 'errors', 'capability', 'state'],
      checks: [],
      summary: { passed: 0, failed: 0, skipped: 0 },
      ok: true,
    };
    expect(formatReport(some).split('\n').at(-2)).toBe(
      '0 passed, 0 failed, 0 skipped in 2.3 s: COMPLIANT (timing not checked)',
    );
  });
});
