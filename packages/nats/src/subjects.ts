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

/** A subject for `device` (`hal.v1.dev.{device}...`), or for the default device when undefined. */
export function subjectFor(name: SubjectName, device?: string): string {
  const [domain, type, action] = SUBJECTS[name];
  return buildSubject({ device, domain, type, action });
}
