// The option vocabulary of `hal`: one parser per kind of value (a number in a range, an integer, a
// distance or an angle with its unit, a port, HOST[:PORT], a hex key, a URL), each refusing bad
// input with the one usage error (`CliError` USAGE, exit 2) and a message that names the option,
// so every command refuses bad input the same way. Output places are in output-place.ts.
import { isIPv6 } from 'node:net';
import { DEFAULT_UDP_PORT } from '@hal/physical';
import { CliError } from './cli-error.js';

/** The usage error every parser throws. */
export function usageError(message: string): CliError {
  return new CliError('USAGE', message);
}

/** A decimal number as people type it: `5`, `-0.25`, `.5`, `1e3`; not `0x10`, ` `, `NaN`. */
const DECIMAL = /^[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$/i;

/** `text` as a finite decimal number, or undefined. */
export function readNumber(text: string): number | undefined {
  if (!DECIMAL.test(text)) return undefined;
  const n = Number(text);
  return Number.isFinite(n) ? n : undefined;
}

/** Where a number must lie; both ends included unless `aboveMin`. */
export interface NumberRange {
  min?: number;
  /** Refuse `min` itself: the number must be greater (`> 0`). */
  aboveMin?: boolean;
  max?: number;
}

function rangeText({ min, aboveMin, max }: NumberRange, unit: string): string {
  const u = unit === '' ? '' : ` ${unit}`;
  if (min !== undefined && max !== undefined) {
    return aboveMin === true ? `in (${min}, ${max}]${u}` : `in ${min}..${max}${u}`;
  }
  if (min !== undefined) return `${aboveMin === true ? '>' : '>='} ${min}${u}`;
  if (max !== undefined) return `<= ${max}${u}`;
  return unit === '' ? '' : `of ${unit}`;
}

function inRange(n: number, { min, aboveMin, max }: NumberRange): boolean {
  if (min !== undefined && (aboveMin === true ? n <= min : n < min)) return false;
  return max === undefined || n <= max;
}

/**
 * A number option in `range`, in `unit` (named in the message only). Refuses what is not a
 * decimal number (`12abc`, `NaN`, `0x10`, an empty word) and what lies outside the range.
 */
export function numberArg(name: string, range: NumberRange = {}, unit = '') {
  return (value: string): number => {
    const n = readNumber(value);
    if (n === undefined || !inRange(n, range)) {
      const where = rangeText(range, unit);
      throw usageError(
        `"${name}" must be a number${where === '' ? '' : ` ${where}`}, got "${value}"`,
      );
    }
    return n;
  };
}

/** A finite number option greater than 0. */
export function positiveArg(name: string, unit = '') {
  return numberArg(name, { min: 0, aboveMin: true }, unit);
}

/**
 * An integer option in `min..max`, written in decimal digits (a leading minus where `min` is
 * negative): `1e3`, `0x10`, `2.0` and ` ` are refused, not read as numbers.
 */
export function integerArg(name: string, min: number, max: number) {
  return (value: string): number => {
    const n = Number(value);
    if (!/^-?\d+$/.test(value) || !Number.isSafeInteger(n) || n < min || n > max) {
      throw usageError(`"${name}" must be an integer in ${min}..${max}, got "${value}"`);
    }
    return n;
  };
}

/** A TCP or UDP port option: 1..65535, or 0 too (any free port) where `anyFree`. */
export function portArg(name: string, { anyFree = false }: { anyFree?: boolean } = {}) {
  return integerArg(name, anyFree ? 0 : 1, 65_535);
}

/** The kinds of quantity typed with a unit, and each unit's factor to the kind's base unit. */
const UNITS = {
  /** Distances, in metres: a bare number is metres in every command. */
  distance: { base: 'm', units: { m: 1, cm: 0.01, mm: 0.001 } },
  /** Angles, in degrees: a bare number is degrees in every command. */
  angle: { base: 'degrees', units: { deg: 1, '°': 1, rad: 180 / Math.PI } },
} as const;

export type QuantityKind = keyof typeof UNITS;

/** How each kind is written, for messages and help: `30cm, 0.3m, 300mm`. */
export const QUANTITY_FORMS: Readonly<Record<QuantityKind, string>> = {
  distance: 'metres, or with a unit: 0.3m, 30cm, 300mm',
  angle: 'degrees, or with a unit: 90deg, 1.5rad',
};

/**
 * `text` as a quantity of `kind` in its base unit (metres, degrees): a bare number is the base
 * unit, a number followed by a unit (`30cm`, `30 cm`, `1.5rad`) is converted. Undefined when it
 * is neither.
 */
export function readQuantity(text: string, kind: QuantityKind): number | undefined {
  const match = /^(.*?)\s*([a-z°]*)$/i.exec(text.trim());
  if (match === null || text.trim() === '') return undefined;
  const [, figure = '', unit = ''] = match;
  const n = readNumber(figure);
  if (n === undefined) return undefined;
  if (unit === '') return n;
  const factor = (UNITS[kind].units as Readonly<Record<string, number>>)[unit.toLowerCase()];
  // 12 significant digits: 7cm is 0.07 m, not 0.07000000000000001
  return factor === undefined ? undefined : Number((n * factor).toPrecision(12));
}

/** `a distance`, `an angle`. */
export function article(kind: QuantityKind): string {
  return kind === 'angle' ? 'an angle' : 'a distance';
}

/**
 * A quantity option (`--spacing 30cm`): its value in the kind's base unit (metres, degrees),
 * within `range` (in that unit).
 */
export function quantityArg(name: string, kind: QuantityKind, range: NumberRange = {}) {
  return (value: string): number => {
    const n = readQuantity(value, kind);
    if (n === undefined) {
      throw usageError(
        `"${name}" must be ${article(kind)}: ${QUANTITY_FORMS[kind]}; got "${value}"`,
      );
    }
    if (!inRange(n, range)) {
      throw usageError(
        `"${name}" must be ${article(kind)} ${rangeText(range, UNITS[kind].base)}, got "${value}"`,
      );
    }
    return n;
  };
}

/** A distance option, in metres (`0.3`, `0.3m`, `30cm`). */
export function distanceArg(name: string, range: NumberRange = {}) {
  return quantityArg(name, 'distance', range);
}

/** An angle option, in degrees (`90`, `90deg`, `1.5rad`). */
export function angleArg(name: string, range: NumberRange = {}) {
  return quantityArg(name, 'angle', range);
}

/** A host and port, the host without the brackets an IPv6 address is written in. */
export interface HostPort {
  host: string;
  port: number;
}

/**
 * `HOST[:PORT]`, `[IPV6]:PORT`, `[IPV6]` or a bare IPv6 address (port `defaultPort`), as `text`
 * reads; undefined when it is none of these or the port is not 1..65535.
 */
export function readHostPort(text: string, defaultPort: number): HostPort | undefined {
  let host: string;
  let port: string | undefined;
  const bracketed = /^\[([^\]\s]+)\](?::(\d{1,5}))?$/.exec(text);
  if (bracketed !== null) {
    host = bracketed[1]!;
    port = bracketed[2];
    if (!isIPv6(host)) return undefined;
  } else if (isIPv6(text)) {
    host = text;
  } else {
    const plain = /^([^:\s[\]]+)(?::(\d{1,5}))?$/.exec(text);
    if (plain === null) return undefined;
    host = plain[1]!;
    port = plain[2];
  }
  const n = port === undefined ? defaultPort : Number(port);
  return n >= 1 && n <= 65_535 ? { host, port: n } : undefined;
}

/** `HOST[:PORT]` or `[IPV6][:PORT]` (port 1..65535, default `DEFAULT_UDP_PORT`, the robot's (protocol section 2)). */
export function hostPortArg(name: string, defaultPort = DEFAULT_UDP_PORT) {
  return (value: string): HostPort => {
    const parsed = readHostPort(value, defaultPort);
    if (parsed === undefined) {
      throw usageError(
        `"${name}" must be HOST, HOST:PORT or [IPV6]:PORT (port 1..65535), got "${value}"`,
      );
    }
    return parsed;
  };
}

/** `host:port` for messages and command lines, an IPv6 host in brackets (`[::1]:4210`). */
export function hostPortText({ host, port }: HostPort): string {
  return `${host.includes(':') ? `[${host}]` : host}:${port}`;
}

/** A robot's pre-shared key: hex, an even number of digits, 1 to 64 bytes. */
export function hexKeyArg(name: string) {
  return (value: string): string => {
    if (!/^([0-9a-fA-F]{2}){1,64}$/.test(value)) {
      throw usageError(`"${name}" must be 1..64 bytes written as hex (an even number of digits)`);
    }
    return value;
  };
}

/** A URL option whose scheme is one of `protocols` (`['http:', 'https:']`). */
export function urlArg(name: string, protocols: readonly string[]) {
  return (value: string): string => {
    const schemes = protocols.map((p) => `${p}//`).join(' or ');
    let url: URL;
    try {
      url = new URL(value);
    } catch {
      throw usageError(`"${name}" must be a ${schemes} URL, got "${value}"`);
    }
    if (!protocols.includes(url.protocol)) {
      throw usageError(`"${name}" must be a ${schemes} URL, got "${value}"`);
    }
    return value;
  };
}
