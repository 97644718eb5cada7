// Every subcommand of `hal`, one module each. A module adds its command to the program; the
// options shared by all (--json) are read through `global()` when it runs (context.ts).
import type { RegisterCommand } from './context.js';
import { registerDrive } from './drive.js';
import { registerServe } from './serve.js';
import { registerStatus } from './status.js';
import { registerLook } from './look.js';
import { registerTeleop } from './teleop.js';
import { registerDiscover } from './discover.js';
import { registerEmulate } from './emulate.js';
import { registerTest } from './test.js';
import { registerFleet } from './fleet.js';
import { registerCalibrate } from './calibrate.js';
import { registerAgent } from './agent.js';
import { registerEval } from './eval.js';
import { registerRecord } from './record.js';
import { registerInspect } from './inspect.js';
import { registerReplay } from './replay.js';
import { registerModel } from './model.js';

import { registerMcp } from './mcp.js';

/** The subcommands, in the order `hal --help` lists them. */
export const COMMANDS: readonly RegisterCommand[] = [
  registerStatus,
  registerLook,
  registerDrive,
  registerTeleop,
  registerCalibrate,
  registerAgent,
  registerEval,
  registerModel,
  registerMcp,
  registerServe,
  registerEmulate,
  registerDiscover,
  registerTest,
  registerFleet,
  registerRecord,
  registerInspect,
  registerReplay,
];
