// Parsers for the `hal` command's option values:
// each checks one kind of value and throws commander's InvalidArgumentError with a message that
// names the option, so both programs refuse bad input the same way.
import { InvalidArgumentError } from 'commander';

/**
 * An integer option in `min..max`, written in decimal digits (a leading minus where `min` is
 * negative): `1e3`, `0x10`, `2.0` and ` ` are refused, not read as numbers.
 */
export function integerArg(name: string, min: number, max: number) {
  return (value: string): number => {
    const n = Number(value);
    if (!/^-?\d+$/.test(value) || !Number.isSafeInteger(n) || n < min || n > max) {
      throw new InvalidArgumentError(
        `"${name}" must be an integer in ${min}..${max}, got "${value}"`,
      );
    }
    return n;
  };
}

/** A finite number option greater than 0. */
export function positiveArg(name: string) {
  return (value: string): number => {
    const n = Number(value);
    if (value.trim() === '' || !Number.isFinite(n) || n <= 0) {
      throw new InvalidArgumentError(`"${name}" must be a number > 0, got "${value}"`);
    }
    return n;
  };
}

/** The UDP port a robot listens on when an address gives none (protocol section 2). */
export const DEFAULT_ROBOT_UDP_PORT = 4210;

/** `HOST` or `HOST:PORT` (port 1..65535, default {@link DEFAULT_ROBOT_UDP_PORT}). */
export function hostPortArg(name: string, defaultPort = DEFAULT_ROBOT_UDP_PORT) {
  return (value: string): { host: string; port: number } => {
    const match = /^([^:\s]+)(?::(\d{1,5}))?$/.exec(value);
    const port = match?.[2] === undefined ? defaultPort : Number(match[2]);
    if (match === null || port < 1 || port > 65_535) {
      throw new InvalidArgumentError(`"${name}" must be HOST or HOST:PORT, got "${value}"`);
    }
    return { host: match[1]!, port };
  };
}

/** A robot's pre-shared key: hex, an even number of digits, at most 64 bytes. */
export function hexKeyArg(value: string): string {
  if (!/^([0-9a-fA-F]{2})+$/.test(value) || value.length > 128) {
    throw new InvalidArgumentError(
      '"--key" must be hex, an even number of digits, at most 64 bytes',
    );
  }
  return value;
}
