export { serveHalOnNats } from './gateway.js';
export { errorPayload } from './error-payload.js';
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
export { wheelPowersFor, wheelVelocities } from './drive-mapping.js';
export type { WheelPowers } from './drive-mapping.js';
export { encodeMessage, decodeMessage } from './codec.js';
export { errorFromPayload } from './device-link.js';
export {
  AckSchema,
  CameraFrameRequestSchema,
  CameraFrameSchema,
  CapabilityAnnouncementSchema,
  DifferentialCommandSchema,
  DifferentialStateSchema,
  ErrorReplySchema,
  HalCallReplySchema,
  HalCallSchema,
  HealthRequestSchema,
  HealthSchema,
  ImuDataSchema,
  QuaternionSchema,
  RangeDataSchema,
  RangeSummarySchema,
  SCHEMAS,
} from './messages.js';
export type {
  CameraFrame,
  CapabilityAnnouncement,
  DifferentialCommand,
  DifferentialState,
  HalCall,
  HalCallReply,
  Health,
  ImuData,
  RangeData,
  RangeSummary,
} from './messages.js';
