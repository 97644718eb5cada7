// The places a command writes to (`-o`, `--record`, `--out`), checked before the first robot call
// or trial: a place that holds something already (without --overwrite), a folder that is not
// there, one that cannot be written, or one on /proc or /sys (where a write cannot succeed, and
// Node's recursive mkdir never returns) is a usage error naming the path and why. Every check is
// bounded in time. `openRecordingFile` is the one way a command opens an MCAP file to record into.
import { constants } from 'node:fs';
import { access, lstat, readdir, stat, statfs } from 'node:fs/promises';
import { dirname, resolve } from 'node:path';
import { Option } from 'commander';
import type { Command } from 'commander';
import { McapRecorder } from '@hal/recorder';
import type { RecorderOptions } from '@hal/recorder';
import { withTimeout, errorMessage } from '@hal/types';
import { usageError } from './values.js';

/** One place a command writes to. */
export interface OutputPlace {
  /** The option that named it, for messages (`--record`, `-o`). */
  option: string;
  /** The path as given. */
  path: string;
  /** A file the command creates, or a folder it writes its files into (created if missing). */
  kind: 'file' | 'folder';
  /** Replace a file that exists, or write into a folder that is not empty (`--overwrite`). */
  overwrite?: boolean;
}

/** How long checking (or opening) a place may take before it is refused. */
export const OUTPUT_CHECK_TIMEOUT_MS = 5000;

/** Filesystems nothing can be recorded on: procfs and sysfs (statfs magic numbers). */
const PSEUDO_FILESYSTEMS: ReadonlyMap<number, string> = new Map([
  [0x9fa0, 'the proc filesystem'],
  [0x62656572, 'the sys filesystem'],
]);

/** The `--overwrite` flag of a command that writes `what`. */
export function addOverwriteOption(command: Command, what: string): Command {
  return command.addOption(
    new Option('--overwrite', `replace ${what} when it exists (default: refuse, before starting)`),
  );
}

function errnoOf(error: unknown): string {
  const code = (error as NodeJS.ErrnoException | undefined)?.code;
  return code ?? errorMessage(error);
}

/** The nearest folder at or above `path` that exists (`path` itself when it is one). */
async function nearestFolder(path: string): Promise<string> {
  for (let at = path; ; at = dirname(at)) {
    try {
      if ((await stat(at)).isDirectory()) return at;
      return dirname(at);
    } catch (error) {
      if (errnoOf(error) !== 'ENOENT' || dirname(at) === at) throw error;
    }
  }
}

async function check(place: OutputPlace): Promise<string> {
  const { option, path, kind } = place;
  const refuse = (why: string) => usageError(`"${option}" ${path}: ${why}`);
  if (path.trim() === '') throw usageError(`"${option}" must name a ${kind}`);
  const full = resolve(path);
  let existing: Awaited<ReturnType<typeof lstat>> | undefined;
  try {
    existing = await lstat(full);
  } catch (error) {
    if (errnoOf(error) !== 'ENOENT') throw refuse(`cannot be read (${errnoOf(error)})`);
  }
  const again = (what: string) => ` (give --overwrite to replace ${what})`;
  let folder: string;
  if (kind === 'file') {
    if (existing?.isDirectory() === true) throw refuse('is a folder, not a file');
    if (existing !== undefined && place.overwrite !== true) throw refuse(`exists${again('it')}`);
    folder = dirname(full);
    const parent = await stat(folder).catch((error: unknown) => {
      throw refuse(
        errnoOf(error) === 'ENOENT'
          ? `its folder ${dirname(path)} does not exist`
          : `its folder cannot be read (${errnoOf(error)})`,
      );
    });
    if (!parent.isDirectory()) throw refuse(`${dirname(path)} is not a folder`);
  } else {
    if (existing !== undefined && !existing.isDirectory())
      throw refuse('exists and is not a folder');
    if (existing !== undefined && place.overwrite !== true) {
      const entries = await readdir(full).catch((error: unknown) => {
        throw refuse(`cannot be read (${errnoOf(error)})`);
      });
      if (entries.length > 0) throw refuse(`is not empty${again('what is there')}`);
    }
    folder = await nearestFolder(full).catch((error: unknown) => {
      throw refuse(`cannot be created (${errnoOf(error)})`);
    });
  }
  // a pseudo filesystem first: root may "write" there, and a recursive mkdir there never returns
  const fsType = await statfs(folder).catch((error: unknown) => {
    throw refuse(`its filesystem cannot be read (${errnoOf(error)})`);
  });
  const kindOfFs = PSEUDO_FILESYSTEMS.get(Number(fsType.type));
  if (kindOfFs !== undefined) throw refuse(`is on ${kindOfFs}, where nothing can be written`);
  await access(folder, constants.W_OK).catch((error: unknown) => {
    throw refuse(`cannot write in ${folder === full ? 'it' : folder} (${errnoOf(error)})`);
  });
  if (existing !== undefined && kind === 'file') {
    await access(full, constants.W_OK).catch((error: unknown) => {
      throw refuse(`cannot be replaced (${errnoOf(error)})`);
    });
  }
  return full;
}

/** Runs `work`, a usage error naming `place` when it takes longer than the bound. */
async function bounded<T>(place: OutputPlace, work: Promise<T>): Promise<T> {
  const done = await withTimeout(work, OUTPUT_CHECK_TIMEOUT_MS);
  if (done === undefined) {
    throw usageError(
      `"${place.option}" ${place.path}: its filesystem did not answer within ${OUTPUT_CHECK_TIMEOUT_MS} ms`,
    );
  }
  return done.value;
}

/**
 * Checks that `place` can be written (see the file's head), within
 * {@link OUTPUT_CHECK_TIMEOUT_MS}: a usage error naming the path and why when not. Resolves the
 * absolute path. Nothing is created.
 */
export async function checkOutputPlace(place: OutputPlace): Promise<string> {
  return bounded(place, check(place));
}

/**
 * Checks `place` (a file) and opens an MCAP recorder on it: a usage error, before anything else
 * runs, when it cannot be written.
 */
export async function openRecordingFile(
  place: Omit<OutputPlace, 'kind'>,
  options: RecorderOptions = {},
): Promise<McapRecorder> {
  const file = { ...place, kind: 'file' as const };
  await checkOutputPlace(file);
  return bounded(
    file,
    McapRecorder.toFile(place.path, options).catch((error: unknown) => {
      throw usageError(`"${place.option}" ${place.path}: cannot be written (${errnoOf(error)})`);
    }),
  );
}
