export { buildProgram, runHal } from './program.js';
export type { ErrorDocument } from './program.js';
export { CliError, CLI_ERROR_CODES } from './cli-error.js';
export type { CliErrorCode } from './cli-error.js';
export { emit, progress } from './io.js';
export { addNatsOptions, deviceIdArg, natsConnectOptions } from './nats-options.js';
export type { NatsCliOptions } from './nats-options.js';
export type { CliIO, GlobalOptions } from './io.js';
export { COMMANDS } from './commands/index.js';
export type { CommandContext, RegisterCommand } from './commands/index.js';
export {
  addTargetOptions,
  describeTarget,
  resolveTarget,
  DEFAULT_CONNECT_TIMEOUT_MS,
  TARGET_KINDS,
} from './target.js';
export type { Target, TargetCliOptions, TargetKind } from './target.js';
export { openTarget, withTarget } from './target-hal.js';
export type { OpenTargetOptions, OpenedHal } from './target-hal.js';
export { computeCalibration } from './calibrate/calibration-math.js';
export type {
  CalibrationResult,
  StraightRun,
  TurnRun,
  WheelGeometry,
} from './calibrate/calibration-math.js';
export { deviceFactories } from './fleet/device-factories.js';
export type { FleetDeviceFactories } from './fleet/device-factories.js';
