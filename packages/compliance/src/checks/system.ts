// The `system` capability every device serves: capability query and announcement, health, and
// the answers to bad input and to subjects the spec does not define.
import { discoverTafyNodes } from '@hal/discovery';
import { LATENCY_CLASSES } from '../spec.js';
import type { Check } from './check.js';
import { fail, pass } from './check.js';
import { formatVerdict, latencyVerdict, refusesVerdict, validReply } from './helpers.js';

const capabilityRequest = (ctx: Parameters<Check['run']>[0]) =>
  ctx.ask(
    ctx.wire.subject('capabilityReq'),
    ctx.wire.envelope('hal/system/capability/req/1.0', {}),
    'capabilities',
  );

const healthRequest = (ctx: Parameters<Check['run']>[0], diagnostics: boolean) =>
  ctx.ask(
    ctx.wire.subject('health'),
    ctx.wire.envelope('hal/system/health/req/1.0', { include_diagnostics: diagnostics }),
    'health',
  );

export const SYSTEM_CHECKS: readonly Check[] = [
  {
    capability: 'system',
    group: 'timing',
    name: 'health',
    title: 'system.health.req round trip',
    run: (ctx) =>
      latencyVerdict(
        ctx,
        ctx.options.samples,
        LATENCY_CLASSES.interactive,
        () => healthRequest(ctx, false),
        validReply,
      ),
  },
  {
    capability: 'system',
    group: 'timing',
    name: 'capability-query',
    title: 'system.capability.req round trip',
    run: (ctx) =>
      latencyVerdict(
        ctx,
        ctx.options.samples,
        LATENCY_CLASSES.interactive,
        () => capabilityRequest(ctx),
        validReply,
      ),
  },
  {
    capability: 'system',
    group: 'format',
    name: 'health-reply',
    title: 'health replies are valid envelopes from the device, with diagnostics when asked',
    run: async (ctx) => {
      const answer = await healthRequest(ctx, true);
      const payload = answer.inspected?.payload;
      if (payload !== undefined && payload.diagnostics === undefined) {
        return fail('include_diagnostics: true was answered without diagnostics.errors');
      }
      return formatVerdict(
        ctx.replies.filter((r) => r.kind === 'health').map((r) => r.inspected),
        'health replies',
      );
    },
  },
  {
    capability: 'system',
    group: 'format',
    name: 'bare-request',
    title: 'a bare spec payload on system.health.req (no envelope) is answered as HAL v1',
    run: async (ctx) => {
      const answer = await ctx.ask(ctx.wire.subject('health'), ctx.wire.bare({}), 'health');
      const problem = validReply(answer);
      if (problem !== undefined) return fail(`a bare health request was answered ${problem}`);
      return pass('a bare {} got a valid health reply');
    },
  },
  {
    capability: 'system',
    group: 'format',
    name: 'capability-reply',
    title: "capability replies are valid, and the envelope's caps are the announced caps",
    run: async (ctx) => {
      const replies = ctx.replies.filter((r) => r.kind === 'capabilities').map((r) => r.inspected);
      const verdict = formatVerdict(replies, 'capability replies');
      if (verdict.status === 'fail') return verdict;
      const want = JSON.stringify([...ctx.caps].sort());
      const differs = replies.find(
        (r) => JSON.stringify([...(r.envelope?.caps ?? [])].sort()) !== want,
      );
      if (differs !== undefined) {
        return fail(
          `envelope caps ${JSON.stringify(differs.envelope?.caps)} differ from the payload's ${want}`,
        );
      }
      return verdict;
    },
  },
  {
    capability: 'system',
    group: 'capability',
    name: 'announcement',
    title: 'system.capability.announce is published and matches the capability query',
    run: async (ctx) => {
      const waitMs =
        ctx.options.announceTimeoutMs - (performance.now() - ctx.announcements.startedAtMs);
      if (ctx.announcements.messages.length === 0 && waitMs > 0) {
        await ctx.announcements.next(waitMs);
      }
      const first = ctx.announcements.messages[0];
      if (first === undefined) {
        return fail(`no announcement within ${ctx.options.announceTimeoutMs} ms`);
      }
      const format = formatVerdict([first.inspected], 'announcement');
      if (format.status === 'fail') return format;
      const announced = JSON.stringify([...(first.inspected.payload?.caps ?? [])].sort());
      const queried = JSON.stringify([...ctx.caps].sort());
      if (announced !== queried)
        return fail(`announced ${announced}, but the query answered ${queried}`);
      return pass(`announced ${ctx.caps.length} capabilities, the same as the query`);
    },
  },
  {
    capability: 'system',
    group: 'capability',
    name: 'mdns-announcement',
    title: 'announced by mDNS as _tafynode._tcp with its device_id and the queried caps in TXT',
    onlyWith: 'mdns',
    run: async (ctx) => {
      const nodes = await discoverTafyNodes({ timeoutMs: ctx.options.mdnsTimeoutMs });
      const node = nodes.find((n) => n.deviceId === ctx.deviceId);
      if (node === undefined) {
        const seen = nodes.map((n) => n.deviceId).join(', ') || 'none';
        return fail(
          `no _tafynode._tcp node with device_id "${ctx.deviceId}" in ${ctx.options.mdnsTimeoutMs} ms (seen: ${seen})`,
        );
      }
      const announced = JSON.stringify([...node.caps].sort());
      const queried = JSON.stringify([...ctx.caps].sort());
      if (announced !== queried) {
        return fail(`the TXT record's caps are ${announced}, the capability query's ${queried}`);
      }
      return pass(`found on port ${node.port} with ${node.caps.length} capabilities`);
    },
  },
  {
    capability: 'system',
    group: 'errors',
    name: 'malformed-json',
    title: 'malformed JSON to system.health.req gets the standard error and changes nothing',
    run: (ctx) =>
      refusesVerdict(
        ctx,
        ctx.wire.subject('health'),
        new TextEncoder().encode('{"hal_major": 1,'),
        ['MALFORMED', 'INVALID_PARAMETER'],
      ),
  },
  {
    capability: 'system',
    group: 'errors',
    name: 'unknown-subject',
    title:
      'a subject the spec does not define gets an error or no responder, never a success or silence',
    run: (ctx) =>
      refusesVerdict(
        ctx,
        ctx.wire.unknownSubject(),
        ctx.drive({ linear_vel_m_per_s: 0.01, angular_vel_rad_per_s: 0, duration_ms: 500 }),
        ['UNKNOWN_COMMAND', 'NOT_IMPLEMENTED'],
        true,
      ),
  },
];
