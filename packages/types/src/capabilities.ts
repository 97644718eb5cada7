import { HalError } from './errors.js';

/** A parsed capability string `{domain}.{type}:v{major}.{minor}[:key=value...]`. */
export interface Capability {
  /** Subsystem, e.g. `locomotion`. */
  domain: string;
  /** Kind within the subsystem, e.g. `differential`. */
  type: string;
  major: number;
  minor: number;
  /** Extra facts, e.g. `{ steps_per_rev: '4096' }`. */
  metadata: Record<string, string>;
}

const NAME = /^[a-z][a-z0-9_]*$/;
const KEY = /^[a-z][a-z0-9_]*$/;
const VALUE = /^[^:=\s]+$/;
const VERSION = /^v(0|[1-9]\d*)\.(0|[1-9]\d*)$/;

function invalid(text: string, why: string): HalError {
  return new HalError('INVALID_PARAMETER', `capability "${text}" ${why}`, {
    details: { capability: text, expected: '{domain}.{type}:v{major}.{minor}[:key=value...]' },
  });
}

/** Parses a capability string; throws INVALID_PARAMETER saying what is wrong. */
export function parseCapability(text: string): Capability {
  const [name, version, ...pairs] = text.split(':');
  const dot = name?.indexOf('.') ?? -1;
  if (name === undefined || dot < 0) throw invalid(text, 'has no "{domain}.{type}" name');
  const domain = name.slice(0, dot);
  const type = name.slice(dot + 1);
  if (!NAME.test(domain)) throw invalid(text, `has an invalid domain "${domain}"`);
  if (!NAME.test(type)) throw invalid(text, `has an invalid type "${type}"`);
  const match = version === undefined ? null : VERSION.exec(version);
  if (match === null) throw invalid(text, 'has no "v{major}.{minor}" version');
  const metadata: Record<string, string> = {};
  for (const pair of pairs) {
    const eq = pair.indexOf('=');
    const key = pair.slice(0, eq);
    const value = pair.slice(eq + 1);
    if (eq < 0 || !KEY.test(key) || !VALUE.test(value)) {
      throw invalid(text, `has metadata "${pair}" that is not key=value`);
    }
    if (key in metadata) throw invalid(text, `repeats the metadata key "${key}"`);
    metadata[key] = value;
  }
  return { domain, type, major: Number(match[1]), minor: Number(match[2]), metadata };
}

/** Formats a capability; metadata keys are written in sorted order so equal capabilities format equally. */
export function formatCapability(capability: Capability): string {
  const { domain, type, major, minor, metadata } = capability;
  if (!NAME.test(domain) || !NAME.test(type)) {
    throw invalid(`${domain}.${type}`, 'has an invalid domain or type');
  }
  if (!Number.isInteger(major) || major < 0 || !Number.isInteger(minor) || minor < 0) {
    throw invalid(`${domain}.${type}:v${major}.${minor}`, 'has an invalid version');
  }
  const pairs = Object.keys(metadata)
    .sort()
    .map((key) => {
      const value = metadata[key] ?? '';
      if (!KEY.test(key) || !VALUE.test(value)) {
        throw invalid(`${domain}.${type}`, `has metadata "${key}=${value}" that is not key=value`);
      }
      return `:${key}=${value}`;
    });
  return `${domain}.${type}:v${major}.${minor}${pairs.join('')}`;
}

/**
 * Whether an offered capability satisfies a required one: same domain and type, same major
 * version, minor at least the required one. Metadata does not take part.
 */
export function isCapabilityCompatible(
  offered: Capability | string,
  required: Capability | string,
): boolean {
  const have = typeof offered === 'string' ? parseCapability(offered) : offered;
  const want = typeof required === 'string' ? parseCapability(required) : required;
  return (
    have.domain === want.domain &&
    have.type === want.type &&
    have.major === want.major &&
    have.minor >= want.minor
  );
}

/** The first offered capability that satisfies `required`, or undefined. */
export function findCapability(
  offered: readonly string[],
  required: Capability | string,
): Capability | undefined {
  for (const text of offered) {
    const capability = parseCapability(text);
    if (isCapabilityCompatible(capability, required)) return capability;
  }
  return undefined;
}

/** The capability strings this library's HALs and tools agree on. */
export const CAPABILITIES = Object.freeze({
  differentialDrive: 'locomotion.differential:v1.0',
  camera: 'vision.camera:v1.0',
  rangeSensors: 'vision.range:v1.0',
  imu: 'vision.imu:v1.0',
  lineSensors: 'vision.line:v1.0',
  led: 'communication.led:v1.0',
  speaker: 'communication.speaker:v1.0',
  sound: 'communication.sound:v1.0',
  emergencyStop: 'safety.estop:v1.0',
  arm: 'manipulation.arm:v1.0',
} as const);

/** Whether a device's capability list offers `required` (see {@link isCapabilityCompatible}). */
export function hasCapability(offered: readonly string[], required: string): boolean {
  return findCapability(offered, required) !== undefined;
}
