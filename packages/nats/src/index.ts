export { serveHalOnNats } from './gateway.js';
export { refuseServedTwice } from './served-probe.js';
export type { ServedProbe } from './served-probe.js';
export type { HalGateway } from './gateway.js';
export type { GatewayOptions } from './gateway-options.js';
export { NatsHAL } from './nats-hal.js';
export type { NatsHALOptions } from './nats-hal.js';
export { openConnection } from './connection.js';
export type { NatsConnectOptions, NatsConnectionSource } from './connection.js';
export { SUBJECTS, subjectFor } from './subjects.js';
export type { SubjectName } from './subjects.js';
export { decodeMessage } from './codec.js';
export {
  AckSchema,
  CameraFrameSchema,
  CapabilityAnnouncementSchema,
  DifferentialCommandSchema,
  DifferentialStateSchema,
  ErrorReplySchema,
  HalCallReplySchema,
  HealthSchema,
  ImuDataSchema,
  RangeDataSchema,
  RangeSummarySchema,
  SCHEMAS,
} from './messages.js';
export type {
  CapabilityAnnouncement,
  DifferentialState,
  Health,
  ImuData,
  RangeData,
} from './messages.js';
