// Option parsers shared by `hal discover` and `hal emulate`.
import { usageError } from '../values.js';

/** An IPv4 address (dotted quad). */
export function ipv4Arg(name: string) {
  return (value: string): string => {
    const parts = value.split('.');
    if (parts.length !== 4 || parts.some((p) => !/^\d{1,3}$/.test(p) || Number(p) > 255)) {
      throw usageError(`"${name}" must be an IPv4 address, got "${value}"`);
    }
    return value;
  };
}
