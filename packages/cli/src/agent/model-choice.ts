// Which model `hal agent` talks to: the local GGUF (the default), or an OpenAI-compatible
// endpoint when --base-url is given. Parsing only; the command loads or reaches it.
import type { AgentEndpoint } from '@hal/agent';
import { isDefaultModelFile, SMALL_MODEL_TOOLS } from '@hal/agent-local';
import { CliError } from '../cli-error.js';

/** The model options as commander parses them. */
export interface ModelCliOptions {
  modelFile?: string;
  baseUrl?: string;
  model?: string;
  tools?: string;
  maxSteps?: number;
  threads?: number;
  context?: number;
}

export type ModelChoice =
  | {
      kind: 'local';
      /** Undefined: the SmolLM2 file `hal model pull` caches (also when it was given by its path). */
      modelFile?: string;
      /** The tools the model is offered; undefined: all of them. */
      offerTools?: readonly string[];
      threads?: number;
      contextSize?: number;
    }
  | { kind: 'endpoint'; endpoint: AgentEndpoint; tools?: readonly string[] };

/**
 * Model requests a run may make when --max-steps is not given. The default SmolLM2-135M does one
 * simple thing right but, measured, never answers that it is done: given more requests it
 * repeats or wanders (a turn after "drive forward 10 cm"). So it gets one; any other model 20.
 */
export const DEFAULT_SMALL_MODEL_STEPS = 1;
export const DEFAULT_STEPS = 20;

function toolList(text: string | undefined): readonly string[] | 'all' | undefined {
  if (text === undefined) return undefined;
  if (text.trim() === 'all') return 'all';
  const names = text
    .split(',')
    .map((name) => name.trim())
    .filter((name) => name !== '');
  if (names.length === 0)
    throw new CliError('USAGE', `"--tools" must be "all" or tool names separated by commas`);
  return names;
}

/**
 * The model the options name. `--base-url` picks an endpoint (its model from --model or
 * $OPENAI_MODEL, its key from $OPENAI_API_KEY only, never the command line); otherwise the local
 * model, with --model-file or the default SmolLM2, which is offered a few tools unless --tools
 * says otherwise.
 */
export function modelChoice(
  options: ModelCliOptions,
  env: Readonly<Record<string, string | undefined>>,
): ModelChoice {
  const tools = toolList(options.tools);
  if (options.baseUrl !== undefined) {
    if (options.modelFile !== undefined)
      throw new CliError('USAGE', 'give --model-file (a local model) or --base-url, not both');
    const model = options.model ?? env['OPENAI_MODEL'];
    if (model === undefined || model.trim() === '')
      throw new CliError('USAGE', '--base-url needs --model <name> (or $OPENAI_MODEL)');
    const apiKey = env['OPENAI_API_KEY'];
    return {
      kind: 'endpoint',
      endpoint: {
        baseUrl: options.baseUrl,
        model,
        ...(apiKey === undefined || apiKey === '' ? {} : { apiKey }),
      },
      ...(tools === undefined || tools === 'all' ? {} : { tools }),
    };
  }
  if (options.model !== undefined)
    throw new CliError('USAGE', '--model names a model of an endpoint: give --base-url too');
  // the default file given by its path is the default model, run as the default is
  const modelFile =
    options.modelFile === undefined || isDefaultModelFile(options.modelFile, env)
      ? undefined
      : options.modelFile;
  const offer =
    tools === 'all'
      ? undefined
      : (tools ?? (modelFile === undefined ? SMALL_MODEL_TOOLS : undefined));
  return {
    kind: 'local',
    ...(modelFile === undefined ? {} : { modelFile }),
    ...(offer === undefined ? {} : { offerTools: offer }),
    ...(options.threads === undefined ? {} : { threads: options.threads }),
    ...(options.context === undefined ? {} : { contextSize: options.context }),
  };
}
