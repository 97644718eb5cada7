// Which agents `hal eval` scores: names from --agent, turned into the agents of @hal/eval. The
// local model is loaded once and shared by its trials; an endpoint's key comes from the
// environment only.
import {
  createLocalChatProvider,
  isDefaultModelFile,
  SKILL_EXAMPLES,
  SKILLS_SYSTEM_PROMPT,
  LocalModelError,
} from '@hal/agent-local';
import type { LocalChatProvider } from '@hal/agent-local';
import {
  cameraNavigationAgent,
  chatAgent,
  claimerAgent,
  naiveAgent,
  navigationAgent,
  oracleAgent,
  parserAgent,
  straightAgent,
} from '@hal/eval';
import type { EvalAgent } from '@hal/eval';
import { toOpenAITools } from '@hal/tools';
import type { Logger } from '@hal/types';
import { DEFAULT_SMALL_MODEL_STEPS } from '../agent/model-choice.js';
import { CliError } from '../cli-error.js';

/** The options that shape the model agents. */
export interface EvalAgentOptions {
  modelFile?: string;
  baseUrl?: string;
  systemPrompt?: string;
  temperature?: number;
  maxSteps?: number;
  threads?: number;
}

/** The agents named, and what to free when the run is over. */
export interface EvalAgents {
  agents: EvalAgent[];
  /** Whether one of them is the local model (its trials run one at a time). */
  local: boolean;
  dispose(): Promise<void>;
}

const FIXED: Record<string, () => EvalAgent> = {
  oracle: oracleAgent,
  naive: naiveAgent,
  claimer: claimerAgent,
  straight: straightAgent,
  nav: () => navigationAgent({ name: 'nav:goal-seeking' }),
  'nav-camera': () => cameraNavigationAgent(),
  parser: parserAgent,
};

/** Parses `--agent oracle,naive,local,openai:gpt-4o-mini` (names checked before anything loads). */
export function agentNames(text: string): string[] {
  const names = text
    .split(',')
    .map((n) => n.trim())
    .filter((n) => n !== '');
  if (names.length === 0) throw new CliError('USAGE', '"--agent" names no agent');
  for (const name of names) {
    if (name in FIXED || name === 'local') continue;
    if (/^openai:[^\s]+$/.test(name)) continue;
    throw new CliError(
      'USAGE',
      `"--agent": unknown agent "${name}" (oracle, naive, claimer, straight, parser, nav, nav-camera, local, openai:MODEL)`,
    );
  }
  if (new Set(names).size !== names.length)
    throw new CliError('USAGE', '"--agent" names an agent twice');
  return names;
}

/**
 * Builds the agents; loads the local model when it is named (a model that cannot load is a
 * FAILED error before any trial). llama.cpp's own warnings go to `logger`.
 */
export async function buildAgents(
  names: readonly string[],
  options: EvalAgentOptions,
  env: Readonly<Record<string, string | undefined>>,
  logger?: Logger,
): Promise<EvalAgents> {
  let local: LocalChatProvider | undefined;
  // the default file given by its path is the default model, run as the default is
  const modelFile =
    options.modelFile === undefined || isDefaultModelFile(options.modelFile, env)
      ? undefined
      : options.modelFile;
  const agents: EvalAgent[] = [];
  for (const name of names) {
    const fixed = FIXED[name];
    if (fixed !== undefined) {
      agents.push(fixed());
      continue;
    }
    if (name === 'local') {
      try {
        local = await createLocalChatProvider({
          ...(modelFile === undefined ? {} : { modelFile }),
          // the skills, shown by worked runs; a first reply that calls one (see hal agent)
          examples: SKILL_EXAMPLES,
          callFirst: true,
          ...(options.threads === undefined ? {} : { threads: options.threads }),
          ...(options.temperature === undefined ? {} : { temperature: options.temperature }),
          ...(logger === undefined ? {} : { logger }),
          env,
        });
      } catch (error) {
        throw error instanceof LocalModelError
          ? new CliError('FAILED', `${error.code}: ${error.message}`)
          : error;
      }
      const provider = local;
      const modelName = provider.modelFile.split(/[\\/]/).pop() ?? provider.modelFile;
      const systemPrompt =
        options.systemPrompt ?? (modelFile === undefined ? SKILLS_SYSTEM_PROMPT : undefined);
      agents.push(
        chatAgent({
          name: `local:${modelName.replace(/\.gguf$/i, '')}`,
          provider,
          prepare: (tools) => provider.prepare(toOpenAITools(tools)),
          ...(systemPrompt === undefined ? {} : { systemPrompt }),
          // a small model is offered the skills: a few tools that each do a whole step
          toolProfile: 'skills',
          maxSteps: options.maxSteps ?? (modelFile === undefined ? DEFAULT_SMALL_MODEL_STEPS : 20),
        }),
      );
      continue;
    }
    const model = name.slice('openai:'.length);
    const apiKey = env['OPENAI_API_KEY'];
    agents.push(
      chatAgent({
        name,
        endpoint: {
          baseUrl: options.baseUrl ?? env['OPENAI_BASE_URL'] ?? 'https://api.openai.com/v1',
          model,
          ...(apiKey === undefined || apiKey === '' ? {} : { apiKey }),
        },
        ...(options.systemPrompt === undefined ? {} : { systemPrompt: options.systemPrompt }),
        ...(options.temperature === undefined ? {} : { temperature: options.temperature }),
        ...(options.maxSteps === undefined ? {} : { maxSteps: options.maxSteps }),
      }),
    );
  }
  return {
    agents,
    local: local !== undefined,
    dispose: async () => {
      await local?.dispose().catch(() => undefined);
    },
  };
}
