// The `hal` program: the root command, its shared options, and every subcommand from
// commands/index.ts. Built fresh per run so tests can run many in one process.
import { createRequire } from 'node:module';
import { Command, CommanderError } from 'commander';
import { isHalError, errorMessage } from '@hal/types';
import { CliError } from './cli-error.js';
import { COMMANDS } from './commands/index.js';
import type { CliIO, GlobalOptions } from './io.js';

// src/ and dist/ both sit one folder below the package's manifest
const { version } = createRequire(import.meta.url)('../package.json') as { version: string };

/** Builds the program; commander's exits become thrown CommanderErrors. */
export function buildProgram(io: CliIO): Command {
  const program = new Command('hal')
    .description('Drive, serve, find, test and group robots of the HAL (simulated or physical).')
    .option('--json', 'machine-readable output: JSON lines on stdout, errors as JSON', false)
    .showHelpAfterError('(run with --help for usage)')
    .exitOverride()
    .configureOutput(output(io))
    .version(version);
  const global = (): GlobalOptions => ({ json: program.opts<{ json: boolean }>().json });
  for (const register of COMMANDS) register(program, { io, global });
  // every subcommand, nested ones too (`hal fleet health`), reports its usage errors through the
  // CLI's output and exits the same way, never through process.exit
  const pending = [...program.commands];
  for (let sub = pending.pop(); sub !== undefined; sub = pending.pop()) {
    sub.exitOverride().configureOutput(output(io));
    pending.push(...sub.commands);
  }
  return program;
}

/**
 * Where commander writes: the CLI's output, and a usage error in the CLI's one-line form
 * (`hal: USAGE: message`, as every other failure), not commander's `error: message`.
 */
function output(io: CliIO) {
  return {
    writeOut: (s: string) => io.out(s),
    writeErr: (s: string) => io.err(s),
    outputError: (s: string, write: (s: string) => void) =>
      write(withNegativeHint(s).replace(/^error: /, 'hal: USAGE: ')),
  };
}

/**
 * Commander reads `-5cm` (a negative value with its unit, where `-5` alone is taken as a number)
 * as an unknown option: says how to give it.
 */
function withNegativeHint(message: string): string {
  const value = /unknown option '(-[\d.][^']*)'/.exec(message)?.[1];
  if (value === undefined) return message;
  return message.replace(
    `unknown option '${value}'`,
    `unknown option '${value}' (a negative value with a unit goes after --: ... -- ${value})`,
  );
}

/** The JSON shape of an error with --json. */
export interface ErrorDocument {
  error: { code: string; message: string; details?: unknown };
}

function describeError(error: unknown): { doc: ErrorDocument; exitCode: number } {
  if (error instanceof CliError) {
    return {
      doc: { error: { code: error.code, message: error.message } },
      exitCode: error.exitCode,
    };
  }
  if (isHalError(error)) {
    const details = error.details;
    return {
      doc: { error: { code: error.code, message: error.message, ...(details ? { details } : {}) } },
      exitCode: 1,
    };
  }
  const message = errorMessage(error);
  return { doc: { error: { code: 'FAILED', message } }, exitCode: 1 };
}

/**
 * Runs `hal` with `argv` (without node and the script) and resolves its exit code: 0 on success,
 * 2 on a usage error, 1 on any other failure (written to stderr as `hal: CODE: message`, or as a
 * JSON error document with --json). Never throws.
 */
export async function runHal(argv: readonly string[], io: CliIO): Promise<number> {
  return runProgram(buildProgram(io), argv, io);
}

/** Stops `program` and its subcommands writing usage errors (and the help after them). */
function silenceErrorText(program: Command): void {
  const pending = [program];
  for (let command = pending.pop(); command !== undefined; command = pending.pop()) {
    command.configureOutput({ writeErr: () => undefined, outputError: () => undefined });
    pending.push(...command.commands);
  }
}

/**
 * Refuses a first word that is no command of `program` (`hal nosuch --help`), as commander does
 * without `--help`, where commander would print the root help and exit 0 instead. `hal help
 * nosuch` is refused the same way.
 */
function refuseUnknownCommand(program: Command, argv: readonly string[]): void {
  const words = argv.filter((arg) => !arg.startsWith('-'));
  const known = (name: string | undefined) =>
    name === undefined ||
    program.commands.some((c) => c.name() === name || c.aliases().includes(name));
  const [first, second] = words;
  const named = first === 'help' ? second : first;
  if (first === 'help' || !known(first)) {
    if (!known(named)) {
      program.error(`error: unknown command '${named}'`, {
        exitCode: 2,
        code: 'commander.unknownCommand',
      });
    }
  }
}

/** Runs an already built program (see {@link runHal}); tests add commands to it first. */
export async function runProgram(
  program: Command,
  argv: readonly string[],
  io: CliIO,
): Promise<number> {
  const json = argv.includes('--json');
  // with --json an error is one JSON document: commander's own text would be a second copy
  if (json) silenceErrorText(program);
  try {
    refuseUnknownCommand(program, argv);
    await program.parseAsync([...argv], { from: 'user' });
    return 0;
  } catch (error) {
    if (error instanceof CommanderError) {
      // help and --version end here too, with exit code 0; usage errors were already written
      if (error.exitCode === 0) return 0;
      if (json) {
        const message = withNegativeHint(error.message).replace(/^error: /, '');
        io.err(`${JSON.stringify({ error: { code: 'USAGE', message } })}\n`);
      }
      return 2;
    }
    const { doc, exitCode } = describeError(error);
    if (json) io.err(`${JSON.stringify(doc)}\n`);
    else io.err(`hal: ${doc.error.code}: ${doc.error.message}\n`);
    return exitCode;
  }
}
