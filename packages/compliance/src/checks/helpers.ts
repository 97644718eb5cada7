import type { HalErrorPayload } from '@hal/types';
import type { Answer, RunContext } from '../context.js';
import { describeAnswer } from '../context.js';
import type { Inspected } from '../inspect.js';
import { summarize } from '../stats.js';
import { CHECK_GROUPS } from '../report.js';
import { STREAM_RATE_HZ } from '../spec.js';
import type { LatencyClass } from '../spec.js';
import type { Received, StreamView } from '../streams.js';
import { fail, pass, skip, sleep } from './check.js';
import type { Verdict } from './check.js';

/** The format verdict over messages of one kind: every one a valid envelope and payload. */
export function formatVerdict(messages: readonly Inspected<unknown>[], what: string): Verdict {
  if (messages.length === 0) return fail(`no ${what} was received to check`);
  const bad = messages.filter((m) => m.issues.length > 0);
  if (bad.length === 0) return pass(`${messages.length} ${what} valid`);
  const issues = [...new Set(bad.flatMap((m) => m.issues))].slice(0, 3);
  return fail(`${bad.length} of ${messages.length} ${what} invalid: ${issues.join('; ')}`);
}

/**
 * The format verdict over replies that other checks' requests brought. None at all, in a run that
 * left out some groups, is a skip (those checks sent nothing), not a failure of the device.
 */
export function repliesVerdict(
  ctx: RunContext,
  replies: readonly Inspected<unknown>[],
  what: string,
): Verdict {
  if (replies.length === 0 && ctx.groups.length < CHECK_GROUPS.length) {
    return skip(`no ${what} to check: the checks that send them are in groups not run`);
  }
  return formatVerdict(replies, what);
}

/** Waits until `stream` has been watched for the run's stream window (from its first subscription). */
export async function watched(ctx: RunContext, stream: StreamView): Promise<void> {
  const waitMs = ctx.options.streamWindowMs - (performance.now() - stream.startedAtMs);
  if (waitMs > 0) await sleep(waitMs);
}

/**
 * Times `n` requests; each answer must pass `accept` (which says what is wrong, or undefined).
 * The verdict holds the judged percentile to the class limit.
 */
export async function latencyVerdict(
  ctx: RunContext,
  n: number,
  latencyClass: LatencyClass,
  once: () => Promise<Answer<unknown>>,
  accept: (answer: Answer<unknown>) => string | undefined,
  after?: () => Promise<void>,
): Promise<Verdict> {
  const latencies: number[] = [];
  for (let i = 0; i < n; i += 1) {
    const answer = await once();
    const problem = accept(answer);
    if (problem !== undefined) {
      const measured = summarize(latencies);
      return fail(`request ${i + 1} of ${n}: ${problem}`, { measured, latencyClass });
    }
    latencies.push(answer.outcome.latencyMs);
    if (after !== undefined) await after();
  }
  const measured = summarize(latencies);
  const judged = ctx.options.judge === 'p50' ? measured.p50Ms : measured.p99Ms;
  const text = `${ctx.options.judge} ${judged.toFixed(2)} ms against the ${latencyClass.name} class (< ${latencyClass.limitMs} ms)`;
  return judged < latencyClass.limitMs
    ? pass(text, { measured, latencyClass })
    : fail(text, { measured, latencyClass });
}

/** Accepts a valid reply of the expected kind (no error, no format issue). */
export function validReply(answer: Answer<unknown>): string | undefined {
  const inspected = answer.inspected;
  if (inspected?.payload !== undefined && inspected.error === undefined) return undefined;
  return describeAnswer(answer);
}

/**
 * Watches `stream` for the stream window and judges its rate against the spec's 10-100 Hz. With
 * `key`, a stream that interleaves several sources (the spec's one-sensor range messages) is
 * judged per source: each must stream at the spec's rate.
 */
export async function rateVerdict(
  ctx: RunContext,
  stream: StreamView,
  what: string,
  key?: (message: Received<unknown>) => string | undefined,
): Promise<Verdict> {
  const from = performance.now();
  await sleep(ctx.options.streamWindowMs);
  const seen = stream.since(from);
  if (key === undefined) return rateOf(seen, what, ctx.options.streamWindowMs);
  const groups = new Map<string, Received<unknown>[]>();
  for (const message of seen) {
    const name = key(message) ?? '(unnamed)';
    groups.set(name, [...(groups.get(name) ?? []), message]);
  }
  if (groups.size === 0) return rateOf(seen, what, ctx.options.streamWindowMs);
  const verdicts = [...groups].map(([name, messages]) => ({
    name,
    verdict: rateOf(messages, `${what} "${name}"`, ctx.options.streamWindowMs),
  }));
  const failed = verdicts.find((v) => v.verdict.status === 'fail');
  if (failed !== undefined) return failed.verdict;
  const slowest = verdicts.reduce((a, b) =>
    (a.verdict.rateHz ?? 0) <= (b.verdict.rateHz ?? 0) ? a : b,
  );
  const text = `${verdicts.length} sources, each ${verdicts.map((v) => `${v.name} ${(v.verdict.rateHz ?? 0).toFixed(1)} Hz`).join(', ')}`;
  return pass(text, {
    ...(slowest.verdict.measured === undefined ? {} : { measured: slowest.verdict.measured }),
    ...(slowest.verdict.rateHz === undefined ? {} : { rateHz: slowest.verdict.rateHz }),
  });
}

function rateOf(seen: readonly Received<unknown>[], what: string, windowMs: number): Verdict {
  if (seen.length < 2) {
    return fail(`${seen.length} ${what} message(s) in ${windowMs} ms: not streaming`);
  }
  const intervals = seen.slice(1).map((m, i) => m.atMs - (seen[i]?.atMs ?? m.atMs));
  const spanMs = (seen.at(-1)?.atMs ?? 0) - (seen[0]?.atMs ?? 0);
  const rateHz = ((seen.length - 1) * 1000) / spanMs;
  const measured = summarize(intervals);
  const text = `${rateHz.toFixed(1)} Hz over ${seen.length} messages (spec: ${STREAM_RATE_HZ.min}-${STREAM_RATE_HZ.max} Hz)`;
  const ok = rateHz >= STREAM_RATE_HZ.min && rateHz <= STREAM_RATE_HZ.max;
  return ok ? pass(text, { measured, rateHz }) : fail(text, { measured, rateHz });
}

/** The error of an answer, if it was the spec's error shape. */
export function errorOf(answer: Answer<unknown>): HalErrorPayload | undefined {
  return answer.inspected?.error;
}

/**
 * Judges an answer that must be the spec's error with one of `codes`; when `orNoResponder`,
 * NATS's no-responders (nobody serves the subject, answered by the server at once) passes too.
 */
export function expectError(
  answer: Answer<unknown>,
  codes: readonly string[],
  orNoResponder = false,
): string | undefined {
  if (orNoResponder && answer.outcome.kind === 'no-responders') return undefined;
  const error = errorOf(answer);
  if (error === undefined)
    return `expected error ${codes.join(' or ')}, got ${describeAnswer(answer)}`;
  const issues = answer.inspected?.issues ?? [];
  if (issues.length > 0) return `the error reply is malformed: ${issues.join('; ')}`;
  if (typeof error.message !== 'string' || error.message === '') return 'the error has no message';
  if (!codes.includes(error.code)) return `expected ${codes.join(' or ')}, got ${error.code}`;
  return undefined;
}

const POSE_EPS_M = 1e-3;
const YAW_EPS_RAD = 1e-3;
const VEL_EPS = 1e-3;

/**
 * Runs `action` and says what it changed, if anything: the pose, motion seen on the state stream
 * meanwhile, the e-stop, or the health status. Undefined: nothing changed.
 */
export async function changedBy(
  ctx: RunContext,
  action: () => Promise<void>,
  settleMs = 400,
): Promise<string | undefined> {
  const before = await ctx.freshState();
  const healthBefore = (await ctx.health())?.status;
  const from = performance.now();
  await action();
  await sleep(settleMs);
  const after = await ctx.freshState();
  const healthAfter = (await ctx.health())?.status;
  if (healthBefore !== healthAfter) {
    return `health went from ${String(healthBefore)} to ${String(healthAfter)}`;
  }
  const moving = ctx.state
    .since(from)
    .map((m) => m.inspected.payload)
    .find(
      (p) =>
        p !== undefined &&
        (Math.abs(p.linear_vel_m_per_s) > VEL_EPS || Math.abs(p.angular_vel_rad_per_s) > VEL_EPS),
    );
  if (moving !== undefined) {
    return `the state stream showed motion (linear ${moving.linear_vel_m_per_s} m/s, angular ${moving.angular_vel_rad_per_s} rad/s)`;
  }
  if (before === undefined || after === undefined) return undefined;
  const dx = after.x_m - before.x_m;
  const dy = after.y_m - before.y_m;
  const dyaw = after.yaw_rad - before.yaw_rad;
  if (Math.hypot(dx, dy) > POSE_EPS_M || Math.abs(dyaw) > YAW_EPS_RAD) {
    return `the pose changed by (${dx.toFixed(4)} m, ${dy.toFixed(4)} m, ${dyaw.toFixed(4)} rad)`;
  }
  if (before.emergency_stopped !== after.emergency_stopped) return 'the e-stop state changed';
  return undefined;
}

/** Sends one bad message and requires the standard error with `codes`, changing nothing. */
export async function refusesVerdict(
  ctx: RunContext,
  subject: string,
  data: Uint8Array,
  codes: readonly string[],
  orNoResponder = false,
): Promise<Verdict> {
  let problem: string | undefined;
  let seen = '';
  const changed = await changedBy(ctx, async () => {
    const answer = await ctx.ask(subject, data, 'ack');
    problem = expectError(answer, codes, orNoResponder);
    seen = describeAnswer(answer);
  });
  if (problem !== undefined) return fail(problem);
  if (changed !== undefined) return fail(`answered ${seen}, but ${changed}`);
  return pass(`answered ${seen}; nothing changed`);
}
