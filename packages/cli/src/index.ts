export { buildProgram, runHal } from './program.js';
export type { ErrorDocument } from './program.js';
export { CliError, CLI_ERROR_CODES } from './cli-error.js';
export type { CliErrorCode } from './cli-error.js';
export { emit, progress } from './io.js';
export type { CliIO, GlobalOptions } from './io.js';
export { COMMANDS } from './commands/index.js';
export type { CommandContext, RegisterCommand } from './commands/index.js';
