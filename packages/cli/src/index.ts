// @hal/cli: the `hal` command. As a library: run it in a process of your own (runHal, with the
// streams of CliIO), read its errors (ErrorDocument, CliError), and build fleet devices the way
// `hal fleet` does (deviceFactories, for @hal/fleet/node's DeviceManager).
export { buildProgram, runHal } from './program.js';
export type { ErrorDocument } from './program.js';
export { CliError, CLI_ERROR_CODES } from './cli-error.js';
export type { CliErrorCode } from './cli-error.js';
export type { CliIO, GlobalOptions } from './io.js';
export { deviceFactories } from './fleet/device-factories.js';
export type { FleetDeviceFactories } from './fleet/device-factories.js';
