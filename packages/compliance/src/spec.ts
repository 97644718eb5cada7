// The figures the runner holds a device to, from the Tafy HAL spec's "Timing and Quality of
// Service" and "Performance Guidelines", and the capabilities it knows how to check.

/** A latency class of the spec: a reply must come within `limitMs`. */
export interface LatencyClass {
  name: 'real-time' | 'low-latency' | 'interactive';
  limitMs: number;
  /** What the spec puts in the class. */
  example: string;
}

/** The spec's latency classes (its fourth, background, has no upper bound and is not checked). */
export const LATENCY_CLASSES = Object.freeze({
  realTime: { name: 'real-time', limitMs: 1, example: 'encoder feedback' },
  lowLatency: { name: 'low-latency', limitMs: 10, example: 'motor commands' },
  interactive: { name: 'interactive', limitMs: 100, example: 'camera frames' },
} as const satisfies Record<string, LatencyClass>);

/** The spec's state stream rate: 10-100 Hz "depending on dynamics". */
export const STREAM_RATE_HZ = Object.freeze({ min: 10, max: 100 });

/** The capabilities the runner checks, by the spec's names (`--capability motor.differential`). */
export const SPEC_CAPABILITIES = [
  'system',
  'motor.differential',
  'safety',
  'camera',
  'sensor.imu',
  'sensor.range',
] as const;
export type SpecCapability = (typeof SPEC_CAPABILITIES)[number];

/**
 * Announced capability names (`{domain}.{type}` before the version) that mean each spec
 * capability: the spec's own name, and the name this library's HALs announce.
 */
const ANNOUNCED_AS: Record<SpecCapability, readonly string[]> = {
  system: [],
  'motor.differential': ['motor.differential', 'locomotion.differential'],
  safety: ['safety.estop'],
  camera: ['camera.frame', 'camera.rgb', 'vision.camera'],
  'sensor.imu': ['sensor.imu', 'vision.imu'],
  'sensor.range': ['sensor.range', 'vision.range'],
};

/** Whether `caps` (capability strings) announce `capability`; `system` is always served. */
export function announces(caps: readonly string[], capability: SpecCapability): boolean {
  if (capability === 'system') return true;
  const names = ANNOUNCED_AS[capability];
  return caps.some((cap) => {
    const name = cap.split(':')[0] ?? '';
    // the spec's sub-typed names count too: sensor.range.tof is a range sensor
    return names.some((n) => name === n || name.startsWith(`${n}.`));
  });
}

/** Parses a `--capability` value; undefined when it is not one the runner knows. */
export function specCapability(name: string): SpecCapability | undefined {
  return (SPEC_CAPABILITIES as readonly string[]).includes(name)
    ? (name as SpecCapability)
    : undefined;
}
