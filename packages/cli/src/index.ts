// @hal/cli: the `hal` command. As a library: run it in a process of your own (runHal, with the
// streams of CliIO), read its errors (ErrorDocument, CliError), and build fleet devices the way
// `hal fleet` does (deviceFactories, for @hal/fleet/node's DeviceManager), and check what
// `hal look --json` prints (LookDocumentSchema).
export { runHal } from './program.js';
export { CliError } from './cli-error.js';
export type { CliErrorCode } from './cli-error.js';
export type { CliIO } from './io.js';
export { deviceFactories } from './fleet/device-factories.js';
export type { FleetDeviceFactories } from './fleet/device-factories.js';
export { LookDocumentSchema } from './look/look-document.js';
export type { LookDocument } from './look/look-document.js';
