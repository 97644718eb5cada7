// Runs the golden exchanges of tests/vectors/protocol-messages.json against a device (the
// emulator over UDP, or the in-process mock robot), decoding every reply with @hal/physical's
// codec and checking it against the reply schemas.
import { readFileSync } from 'node:fs';
import { MessageCodec, REPLY_SCHEMAS } from '@hal/physical/protocol';
import type { WireReply } from '@hal/physical/protocol';
import { HAL_ERROR_CODES } from '@hal/types';
import { expect } from 'vitest';

export interface VectorStep {
  send?: Record<string, unknown>;
  send_raw?: string;
  expect?: Record<string, unknown>;
  expect_absent?: string[];
  same_as_previous?: boolean;
  advance_ms?: number;
}

export interface VectorCase {
  name: string;
  steps: VectorStep[];
}

export const PROTOCOL_CASES = (
  JSON.parse(
    readFileSync(new URL('../vectors/protocol-messages.json', import.meta.url), 'utf8'),
  ) as { cases: VectorCase[] }
).cases;

/** A device under test: send bytes, get the reply bytes; let its clock run. */
export interface VectorDevice {
  exchange(bytes: Uint8Array): Promise<Uint8Array>;
  advance(ms: number): Promise<void>;
}

function substitute(value: unknown, sid: number | undefined): unknown {
  if (value === '$sid') return sid;
  if (Array.isArray(value)) return value.map((v) => substitute(v, sid));
  if (value !== null && typeof value === 'object') {
    return Object.fromEntries(
      Object.entries(value).map(([k, v]) => [k, substitute(v, sid)] as const),
    );
  }
  return value;
}

/** Drops `message` fields (the mock robot words its errors differently). */
function withoutMessages(value: unknown): unknown {
  if (Array.isArray(value)) return value.map(withoutMessages);
  if (value !== null && typeof value === 'object') {
    return Object.fromEntries(
      Object.entries(value)
        .filter(([k]) => k !== 'message' && k !== 'estop_reason')
        .map(([k, v]) => [k, withoutMessages(v)] as const),
    );
  }
  return value;
}

const codec = new MessageCodec();

export async function runCase(
  device: VectorDevice,
  testCase: VectorCase,
  options: { exactMessages: boolean },
): Promise<void> {
  let sid: number | undefined;
  let previous: Uint8Array | undefined;
  for (const [index, step] of testCase.steps.entries()) {
    const where = `${testCase.name} step ${index + 1}`;
    if (step.advance_ms !== undefined) await device.advance(step.advance_ms);
    const request =
      step.send_raw !== undefined
        ? new TextEncoder().encode(step.send_raw)
        : new TextEncoder().encode(JSON.stringify(substitute(step.send, sid)));
    const bytes = await device.exchange(request);
    if (step.same_as_previous) {
      expect(Buffer.from(bytes).toString(), where).toBe(Buffer.from(previous!).toString());
    }
    previous = bytes;
    const decoded = codec.decode(bytes);
    expect(decoded.ok, `${where}: ${Buffer.from(bytes).toString()}`).toBe(true);
    if (!decoded.ok) return;
    const reply: WireReply = decoded.reply;
    // the reply's own data must satisfy the reply schema of its command
    const cmd = (step.send?.['cmd'] ?? reply.cmd) as string | undefined;
    if (reply.ok && cmd !== undefined && cmd in REPLY_SCHEMAS) {
      const schema = REPLY_SCHEMAS[cmd as keyof typeof REPLY_SCHEMAS];
      const parsed = schema.safeParse(reply);
      expect(parsed.success, `${where}: ${JSON.stringify(parsed.error?.issues)}`).toBe(true);
    }
    if (!reply.ok) {
      expect(HAL_ERROR_CODES, where).toContain(reply.error?.code);
    }
    if (cmd === 'hello' && reply.ok) sid = reply.sid;
    if (step.expect !== undefined) {
      const expected = substitute(step.expect, sid) as Record<string, unknown>;
      const actual = JSON.parse(JSON.stringify(reply)) as Record<string, unknown>;
      if (options.exactMessages) {
        expect(actual, where).toMatchObject(expected);
      } else {
        expect(withoutMessages(actual), where).toMatchObject(
          withoutMessages(expected) as Record<string, unknown>,
        );
      }
    }
    for (const field of step.expect_absent ?? []) {
      expect(reply, where).not.toHaveProperty(field);
    }
  }
}
