// What a command module gets when it registers itself on the `hal` program.
import type { Command } from 'commander';
import type { CliIO, GlobalOptions } from '../io.js';

/** What a command module gets when it registers. */
export interface CommandContext {
  io: CliIO;
  /** The root program's shared options, as parsed (read it inside the action, not at registration). */
  global(): GlobalOptions;
}

/** A subcommand: adds itself (and its options and action) to `program`. */
export type RegisterCommand = (program: Command, ctx: CommandContext) => void;
