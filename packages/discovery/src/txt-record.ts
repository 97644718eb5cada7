// The TXT record of an announced robot (docs/discovery.md): checked with zod, the capability list
// joined back from `caps`, `caps1`, `caps2`, ... and every capability string parsed.
import { z } from 'zod';
import { HALConfigSchema, parseCapability, errorMessage } from '@hal/types';
import { MAX_TXT_ENTRY_BYTES, TXT_VERSION } from './service.js';

/** How a robot authenticates requests, as its `auth` TXT entry (and hello's `auth`) says. */
export const ANNOUNCED_AUTH = ['hmac-sha256', 'none', 'unconfigured'] as const;
export type AnnouncedAuth = (typeof ANNOUNCED_AUTH)[number];

const text = (what: string) =>
  z.string({ error: (issue) => `${what} must be text, got ${JSON.stringify(issue.input)}` });

/** The TXT entries a robot announces; unknown entries are ignored. */
export const AnnouncementTxtSchema = z
  .object({
    txtvers: z.literal(TXT_VERSION, { error: `"txtvers" must be "${TXT_VERSION}"` }),
    device_id: HALConfigSchema.shape.deviceId,
    proto: text('"proto"').regex(/^\d+\.\d+$/, '"proto" must be a version like 1.1'),
    auth: z.enum(ANNOUNCED_AUTH, {
      error: `"auth" must be one of ${ANNOUNCED_AUTH.map((a) => `"${a}"`).join(', ')}`,
    }),
    caps: text('"caps"'),
  })
  .catchall(z.unknown());

/** What a robot says about itself in its announcement. */
export interface RobotAnnouncement {
  deviceId: string;
  /** The wire protocol version (`proto`), e.g. `1.1`. */
  protocolVersion: string;
  auth: AnnouncedAuth;
  /** The capability strings, `{domain}.{type}:v{major}.{minor}[:metadata]`. */
  capabilities: string[];
}

export type ParsedAnnouncement =
  { ok: true; announcement: RobotAnnouncement } | { ok: false; reason: string };

/** The capability list, from `caps` and its continuations `caps1`, `caps2`, ... in order. */
function joinCapabilities(txt: Record<string, unknown>): string[] | string {
  const parts: string[] = [];
  for (let i = 0; ; i += 1) {
    const value = txt[i === 0 ? 'caps' : `caps${i}`];
    if (value === undefined) break;
    if (typeof value !== 'string') return `"caps${i === 0 ? '' : i}" must be text`;
    parts.push(value);
  }
  const capabilities = parts.flatMap((part) => (part === '' ? [] : part.split(',')));
  for (const capability of capabilities) {
    try {
      parseCapability(capability);
    } catch (error) {
      return errorMessage(error);
    }
  }
  return capabilities;
}

/** Reads a robot's TXT record; says why when it is not a valid announcement. */
export function parseAnnouncementTxt(txt: unknown): ParsedAnnouncement {
  const parsed = AnnouncementTxtSchema.safeParse(txt);
  if (!parsed.success) {
    return { ok: false, reason: parsed.error.issues.map(describeIssue).join('; ') };
  }
  const capabilities = joinCapabilities(parsed.data);
  if (typeof capabilities === 'string') return { ok: false, reason: capabilities };
  const { device_id: deviceId, proto: protocolVersion, auth } = parsed.data;
  return { ok: true, announcement: { deviceId, protocolVersion, auth, capabilities } };
}

function describeIssue(issue: z.core.$ZodIssue): string {
  const path = issue.path.join('.');
  return path === '' || issue.message.includes(`"${path}"`)
    ? issue.message
    : `"${path}": ${issue.message}`;
}

/** Checks that every `key=value` fits one TXT entry; returns the first that does not. */
export function oversizeTxtEntry(txt: Record<string, string>): string | undefined {
  return Object.entries(txt).find(
    ([key, value]) => Buffer.byteLength(`${key}=${value}`) > MAX_TXT_ENTRY_BYTES,
  )?.[0];
}
