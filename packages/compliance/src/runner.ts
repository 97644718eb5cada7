import { CapabilityAnnouncementSchema, SCHEMAS } from '@hal/nats';
import { HalError, errorMessage } from '@hal/types';
import type { Check, Verdict } from './checks/check.js';
import { CAMERA_CHECKS } from './checks/camera.js';
import { MOTOR_CHECKS } from './checks/motor.js';
import { SAFETY_CHECKS, resetEstop } from './checks/safety.js';
import { SENSOR_CHECKS } from './checks/sensors.js';
import { SYSTEM_CHECKS } from './checks/system.js';
import { RunContext } from './context.js';
import { inspect } from './inspect.js';
import { resolveOptions } from './options.js';
import type { ComplianceOptions } from './options.js';
import { CHECK_GROUPS } from './report.js';
import type { CheckGroup, CheckResult, ComplianceReport } from './report.js';
import { SPEC_CAPABILITIES, announces, specCapability } from './spec.js';
import type { SpecCapability } from './spec.js';
import { DeviceWire } from './wire.js';

/** Every check, in the order they run: capability by capability, motion after refusals. */
export const CHECKS: readonly Check[] = [
  ...SYSTEM_CHECKS,
  ...MOTOR_CHECKS,
  ...SAFETY_CHECKS,
  ...CAMERA_CHECKS,
  ...SENSOR_CHECKS,
];

function selected(capabilities: readonly string[] | undefined): SpecCapability[] {
  if (capabilities === undefined) return [...SPEC_CAPABILITIES];
  return capabilities.map((name) => {
    const capability = specCapability(name);
    if (capability === undefined) {
      throw new HalError(
        'INVALID_PARAMETER',
        `"capability" must be one of ${SPEC_CAPABILITIES.join(', ')}, got "${name}"`,
        { details: { parameter: 'capability', value: name } },
      );
    }
    return capability;
  });
}

function selectedGroups(groups: readonly string[] | undefined): CheckGroup[] {
  if (groups === undefined) return [...CHECK_GROUPS];
  if (groups.length === 0) {
    throw new HalError('INVALID_PARAMETER', '"groups" must name at least one check group', {
      details: { parameter: 'groups' },
    });
  }
  for (const name of groups) {
    if (!(CHECK_GROUPS as readonly string[]).includes(name)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `"groups" must be among ${CHECK_GROUPS.join(', ')}, got "${name}"`,
        { details: { parameter: 'groups', value: name } },
      );
    }
  }
  // in the spec's order, each once
  return CHECK_GROUPS.filter((group) => groups.includes(group));
}

/**
 * Checks a device on NATS against the Tafy HAL spec from the outside, as a client that knows
 * only the spec would: its raw subjects and envelopes. Message format, timing classes, error
 * handling, capability accuracy and state consistency, per capability. Motion checks are small
 * and short, end with a stop, and an e-stop the runner took is always reset, even on failure.
 *
 * Rejects NOT_CONNECTED when no device answers the capability query, TIMEOUT when nothing
 * replies, and MALFORMED when the reply cannot be read; every other finding is in the report.
 */
export async function runCompliance(options: ComplianceOptions): Promise<ComplianceReport> {
  const resolved = resolveOptions(options);
  const capabilities = selected(options.capabilities);
  const groups = selectedGroups(options.groups);
  const startedAt = new Date();
  const t0 = performance.now();
  const wire = new DeviceWire(options.connection, options.device, resolved.clientId);
  const subject = wire.subject('capabilityReq');
  const outcome = await wire.request(subject, wire.envelope(SCHEMAS.capabilities, {}), {
    timeoutMs: resolved.requestTimeoutMs,
  });
  if (outcome.kind === 'no-responders') {
    throw new HalError('NOT_CONNECTED', `no device answers on "${subject}"`, {
      details: { subject },
    });
  }
  if (outcome.kind === 'timeout') {
    throw new HalError(
      'TIMEOUT',
      `no reply on "${subject}" within ${resolved.requestTimeoutMs} ms`,
      {
        details: { subject },
      },
    );
  }
  const first = inspect(outcome.data, CapabilityAnnouncementSchema, options.device);
  if (first.envelope === undefined || first.payload === undefined) {
    throw new HalError(
      'MALFORMED',
      `the capability reply cannot be read: ${first.issues.join('; ')}`,
      {
        details: { subject, issues: first.issues },
      },
    );
  }
  const deviceId = options.device ?? first.envelope.device_id;
  const ctx = new RunContext(wire, deviceId, first.payload, resolved, groups);
  ctx.replies.push({ kind: 'capabilities', subject, inspected: first });
  await wire.flush(); // the stream subscriptions are in place before the first check
  options.onProgress?.({ type: 'device', deviceId, caps: ctx.caps });

  const checks: CheckResult[] = [];
  try {
    for (const check of CHECKS) {
      if (options.signal?.aborted === true) break;
      if (!capabilities.includes(check.capability)) continue;
      if (!groups.includes(check.group)) continue;
      // a check of honest absence does not apply to a capability the device has
      if (check.when === 'unannounced' && announces(ctx.caps, check.capability)) continue;
      if (check.onlyWith === 'mdns' && !resolved.mdns) continue;
      const result = await runOne(ctx, check, options.onProgress);
      checks.push(result);
      options.onProgress?.({ type: 'result', result });
    }
  } finally {
    await leaveSafely(ctx);
    wire.close();
  }
  const count = (status: CheckResult['status']) => checks.filter((c) => c.status === status).length;
  const summary = { passed: count('pass'), failed: count('fail'), skipped: count('skip') };
  return {
    aborted: options.signal?.aborted === true,
    deviceId,
    addressed: options.device,
    deviceType: ctx.announcement.device_type,
    mode: ctx.announcement.mode,
    caps: ctx.caps,
    capabilities,
    groups,
    judge: resolved.judge,
    checks,
    summary,
    ok: summary.failed === 0 && options.signal?.aborted !== true,
    startedAt: startedAt.toISOString(),
    durationMs: Math.round(performance.now() - t0),
  };
}

async function runOne(
  ctx: RunContext,
  check: Check,
  onProgress: ComplianceOptions['onProgress'],
): Promise<CheckResult> {
  const id = `${check.capability}/${check.group}/${check.name}`;
  const base = { id, capability: check.capability, group: check.group, title: check.title };
  if (check.when !== 'unannounced' && !announces(ctx.caps, check.capability)) {
    const reason = `the device does not announce ${check.capability} (it announces ${ctx.caps.join(', ') || 'nothing'})`;
    return { ...base, status: 'skip', reason, durationMs: 0 };
  }
  onProgress?.({ type: 'start', id, title: check.title });
  const started = performance.now();
  let verdict: Verdict;
  try {
    verdict = await check.run(ctx);
  } catch (error) {
    verdict = {
      status: 'fail',
      reason: `the check failed: ${errorMessage(error)}`,
    };
  }
  const durationMs = Math.round(performance.now() - started);
  // A failed check may have left the robot moving (a drive it should have refused, say): stop it
  // before the next check, so one fault fails one check and not the ones after it.
  if (verdict.status === 'fail' && announces(ctx.caps, 'motor.differential')) {
    try {
      await ctx.bringToRest();
    } catch {
      // the device is gone: the next check will say so
    }
  }
  return { ...base, ...verdict, durationMs };
}

/** Whatever happened: the robot is told to stop, and an e-stop the runner took is reset. */
async function leaveSafely(ctx: RunContext): Promise<void> {
  try {
    if (announces(ctx.caps, 'motor.differential')) await ctx.stop();
  } catch {
    // the device is gone: nothing to stop
  }
  for (let attempt = 0; ctx.estopHeld && attempt < 3; attempt += 1) {
    try {
      await resetEstop(ctx);
    } catch {
      // try again
    }
  }
}
