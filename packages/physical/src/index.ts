// @hal/physical: PhysicalHAL and what a user of it needs (its options, the transports it can be
// given, calibration files, the camera reader). The wire protocol's pieces are in
// @hal/physical/protocol; the in-process mock robot is in @hal/physical/testing.
export { PhysicalHAL } from './hal/physical-hal.js';
export { WireBinding } from './hal/wire-binding.js';
export type { PhysicalHALOptions, RobotIdentity } from './hal/options.js';
export type { StartPose } from './pose-tracker.js';
export type { CalibrationSource, RobotCalibration, WheelCalibration } from './hal/calibration.js';
export {
  calibrationDir,
  calibrationOf,
  calibrationPath,
  CalibrationFileSchema,
  canNameFile,
  readCalibrationFile,
  writeCalibrationFile,
} from './calibration/calibration-file.js';
export type { CalibrationFile } from './calibration/calibration-file.js';
export { calibratedGeometry, calibrationSource } from './calibration/calibration-source.js';
export { DEVICE_SETTING_RANGES } from './protocol/device-config.js';
export type { SettingRange } from './protocol/device-config.js';

export type { SafetyLaneTiming } from './safety-lane.js';
export type { SessionState } from './session.js';
export type { ReportedSteps } from './pose-tracker.js';
// the types of PhysicalHALOptions' fields (the schemas themselves: @hal/physical/protocol)
export type { AuthScheme, DeviceConfig } from './protocol/schemas.js';

export type {
  RequestOptions,
  SerialLinkStats,
  Transport,
  TransportContext,
  TransportFactory,
  TransportStats,
} from './transport/transport.js';
export { DEFAULT_UDP_PORT, udpTransport } from './transport/udp.js';
export type { UdpTransport, UdpTransportOptions } from './transport/udp.js';
export { serialTransport } from './transport/serial.js';
export type {
  SerialPortLike,
  SerialPortOpener,
  SerialTransportOptions,
} from './transport/serial.js';

export { MjpegCamera } from './camera/mjpeg.js';
export type { MjpegCameraOptions, MjpegStats } from './camera/mjpeg.js';
