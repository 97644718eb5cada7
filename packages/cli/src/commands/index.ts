// Every subcommand of `hal`, one module each. A module adds its command to the program; the
// options shared by all (--json) are read through `global()` when it runs.
import type { Command } from 'commander';
import type { CliIO, GlobalOptions } from '../io.js';
import { registerDrive } from './drive.js';
import { registerServe } from './serve.js';
import { registerStatus } from './status.js';
import { registerTeleop } from './teleop.js';
import { registerDiscover } from './discover.js';
import { registerEmulate } from './emulate.js';
import { registerTest } from './test.js';
import { registerFleet } from './fleet.js';
import { registerCalibrate } from './calibrate.js';
import { registerAgent } from './agent.js';
import { registerMcp } from './mcp.js';

/** What a command module gets when it registers. */
export interface CommandContext {
  io: CliIO;
  /** The root program's shared options, as parsed (read it inside the action, not at registration). */
  global(): GlobalOptions;
}

/** A subcommand: adds itself (and its options and action) to `program`. */
export type RegisterCommand = (program: Command, ctx: CommandContext) => void;

/** The subcommands, in the order `hal --help` lists them. */
export const COMMANDS: readonly RegisterCommand[] = [
  registerStatus,
  registerDrive,
  registerTeleop,
  registerCalibrate,
  registerAgent,
  registerMcp,
  registerServe,
  registerEmulate,
  registerDiscover,
  registerTest,
  registerFleet,
];
