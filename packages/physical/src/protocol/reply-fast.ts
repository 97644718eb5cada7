import { MOVE_OUTCOMES } from './schemas.js';
import type { Command, ReplyOf } from './schemas.js';

/*
 * The data of the most frequent successful replies (set_led, heartbeat, get_status and the motion
 * commands), checked by hand on the hot path: zod copies the reply field by field through its
 * checks and allocates about as much again as the copy. This path builds the same output (the
 * known fields only, unknown ones stripped) and only ever accepts: anything it is not sure of (a
 * `null` to turn into absent, a value of the wrong type, a non-plain object) goes to the
 * command's zod schema in REPLY_SCHEMAS, which stays the definition. The property test in
 * reply-fast.property.test.ts holds the two equal: whatever this path accepts, the schema accepts
 * with the same output.
 */

/** How one field is checked; a trailing `?` makes it optional (absent; `null` goes to zod). */
type Kind = 'byte' | 'int' | 'uint32' | 'finite' | 'bool' | 'string' | 'outcome';
type Spec = Readonly<Record<string, Kind | `${Kind}?` | Shape>>;
interface Shape {
  readonly shape: Spec;
  readonly optional: boolean;
}

const UINT32_MAX = 4_294_967_295;
const OUTCOMES: ReadonlySet<unknown> = new Set(MOVE_OUTCOMES);

function fits(kind: string, value: unknown): boolean {
  switch (kind) {
    case 'byte':
      return Number.isSafeInteger(value) && (value as number) >= 0 && (value as number) <= 255;
    case 'int':
      return Number.isSafeInteger(value);
    case 'uint32':
      return (
        Number.isSafeInteger(value) && (value as number) >= 0 && (value as number) <= UINT32_MAX
      );
    case 'finite':
      return Number.isFinite(value);
    case 'bool':
      return typeof value === 'boolean';
    case 'string':
      return typeof value === 'string';
    case 'outcome':
      return OUTCOMES.has(value);
    default:
      return false;
  }
}

const isPlain = (value: unknown): value is Record<string, unknown> =>
  typeof value === 'object' && value !== null && Object.getPrototypeOf(value) === Object.prototype;

/** The checked copy of `value` (known fields only), or undefined when zod must decide. */
function check(spec: Spec, value: unknown): Record<string, unknown> | undefined {
  if (!isPlain(value)) return undefined;
  const out: Record<string, unknown> = {};
  for (const key in spec) {
    const kind = spec[key]!;
    const field = value[key];
    if (typeof kind === 'object') {
      if (field === undefined && kind.optional && !Object.hasOwn(value, key)) continue;
      const nested = check(kind.shape, field);
      if (nested === undefined) return undefined;
      out[key] = nested;
      continue;
    }
    const optional = kind.endsWith('?');
    // a key present with the value undefined cannot come from JSON, and zod keeps it
    if (field === undefined && optional && !Object.hasOwn(value, key)) continue;
    if (!fits(optional ? kind.slice(0, -1) : kind, field)) return undefined;
    out[key] = field;
  }
  return out;
}

const LED: Shape = {
  shape: { r: 'byte', g: 'byte', b: 'byte', pattern: 'string' },
  optional: false,
};
const MOTION: Spec = {
  move_id: 'uint32',
  left_steps: 'int?',
  right_steps: 'int?',
  speed: 'finite?',
  speed_clamped: 'bool?',
  duration_ms: 'int?',
  duration_us: 'int?',
  left_sps: 'finite?',
  right_sps: 'finite?',
  running: 'bool?',
};
const STATUS: Spec = {
  x_cm: 'finite',
  y_cm: 'finite',
  heading_rad: 'finite',
  left_steps: 'int',
  right_steps: 'int',
  running: 'bool',
  move_id: 'uint32',
  move_outcome: 'outcome',
  move_left_steps: 'int',
  move_right_steps: 'int',
  left_sps: 'finite',
  right_sps: 'finite',
  uptime_ms: 'int',
  safety: {
    shape: {
      estop: 'bool',
      estop_reason: 'string',
      trips: 'int',
      last_trip: {
        shape: { reason: 'string', detail: 'string', uptime_ms: 'int' },
        optional: true,
      },
      host_timeout_ms: 'int',
      ms_since_host: 'int',
      coils_on: 'bool',
    },
    optional: false,
  },
  led: LED,
};

const FAST: Partial<Record<Command, Spec>> = {
  set_led: { led: LED },
  heartbeat: { uptime_ms: 'int', running: 'bool', estop: 'bool' },
  get_status: STATUS,
  move_steps: MOTION,
  move_cm: MOTION,
  rotate_deg: MOTION,
  drive: MOTION,
};

/** The checked data of a successful reply to `cmd` when this path is sure of it, else undefined. */
export function fastReply<C extends Command>(cmd: C, reply: unknown): ReplyOf<C> | undefined {
  const spec = FAST[cmd];
  // unknown keys (`__proto__` among them) are not copied, as zod strips them
  return spec === undefined ? undefined : (check(spec, reply) as ReplyOf<C> | undefined);
}
