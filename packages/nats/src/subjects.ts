import { buildSubject } from '@hal/types';

/** The subjects the gateway serves, as `[domain, type, action]`. */
export const SUBJECTS = Object.freeze({
  differentialCmd: ['motor', 'differential', 'cmd'],
  differentialState: ['motor', 'differential', 'state'],
  imuData: ['sensor', 'imu', 'data'],
  rangeData: ['sensor', 'range', 'data'],
  rangeSummary: ['sensor', 'range', 'all'],
  cameraFrame: ['camera', 'frame', 'req'],
  health: ['system', 'health', 'req'],
  capabilityReq: ['system', 'capability', 'req'],
  capabilityAnnounce: ['system', 'capability', 'announce'],
  estop: ['safety', 'estop', 'cmd'],
  estopReset: ['safety', 'estop', 'reset'],
  call: ['hal', 'call', 'req'],
  log: ['hal', 'log', 'pub'],
  heartbeat: ['system', 'heartbeat', 'pub'],
} as const);
export type SubjectName = keyof typeof SUBJECTS;

/** Subjects already built (a gateway publishes several per robot at every state tick). */
const built = new Map<string, string>();
const BUILT_MAX = 4096;

/** A subject for `device` (`hal.v1.dev.{device}...`), or for the default device when undefined. */
export function subjectFor(name: SubjectName, device?: string): string {
  const key = device === undefined ? name : `${name}\u0000${device}`;
  const known = built.get(key);
  if (known !== undefined) return known;
  const [domain, type, action] = SUBJECTS[name];
  // a device id that makes no valid subject throws here, every time: only good ones are kept
  const subject = buildSubject({ device, domain, type, action });
  if (built.size >= BUILT_MAX) built.clear();
  built.set(key, subject);
  return subject;
}
