import { basename } from 'node:path';
import type { ChatProvider, ChatReply, ChatRequest, ChatTool, ChatTurn } from '@hal/agent';
import { scoped, errorMessage } from '@hal/types';
import type { Logger } from '@hal/types';
import type { Llama, LlamaContext, LlamaGrammar, LlamaLogLevel, LlamaModel } from 'node-llama-cpp';
import { LocalModelError } from './errors.js';
import { replyGrammar } from './grammar.js';
import { DEFAULT_ANSWER_MAX_LENGTH, replySchema } from './grammar-schema.js';
import { fitHistory } from './history.js';
import type { ExampleRun } from './example-run.js';
import { loadNodeLlamaCpp } from './load-llama.js';
import { checkModelFile, defaultModelFile } from './model-file.js';
import { systemText } from './prompt.js';
import { readReply } from './reply-json.js';
import { defaultThreads } from './threads.js';

/** Options of {@link createLocalChatProvider}. */
export interface LocalChatProviderOptions {
  /** A GGUF model file. Default the SmolLM2-135M file `hal model pull` caches. */
  modelFile?: string;
  /** 'auto' (default): a GPU when llama.cpp finds one and its build is installed, else the CPU. */
  gpu?: 'auto' | false;
  /** CPU threads. Default one fewer than the machine's cores, 1 to 4 ({@link defaultThreads}). */
  threads?: number;
  /** The context window, tokens. Default 2048 (or the model's own, when smaller). */
  contextSize?: number;
  /** Most tokens in one reply. Default 96 (a tool call takes about 20). */
  maxTokens?: number;
  /** Sampling temperature. Default 0: greedy, the same reply for the same prompt. */
  temperature?: number;
  /**
   * Only these of the executor's tools reach the model (a small model picks among few better).
   * Default all of them. A name the executor does not have is a CONFIG error at the first request.
   */
  offerTools?: readonly string[];
  /**
   * The first reply must call a tool (its grammar has no answer): a robot's task always needs at
   * least one look or motion, and a small model otherwise answers from its examples without
   * either. Default false.
   */
  callFirst?: boolean;
  /**
   * Worked example runs the model reads before each conversation, as turns of its own (see
   * SKILL_EXAMPLES). Default none.
   */
  examples?: readonly ExampleRun[];
  /**
   * Longest answer text, characters. Default 240. Up to 256 the grammar holds it; a longer limit
   * is checked after generation (the answer is cut to it).
   */
  answerMaxLength?: number;
  /** llama.cpp's warnings and errors go here (never to the console). */
  logger?: Logger;
  /** For the default model's location (XDG_CACHE_HOME). Default `process.env`. */
  env?: Readonly<Record<string, string | undefined>>;
}

/** A loaded local model, ready for `runAgent({ provider })`. Dispose it when done. */
export interface LocalChatProvider extends ChatProvider {
  readonly modelFile: string;
  /** The context window in use, tokens. */
  readonly contextTokens: number;
  /** The GPU in use ('cuda', 'vulkan', 'metal'), or false on the CPU. */
  readonly gpu: string | false;
  /** Builds (and caches) the grammar for `tools` now: refuses an unexpressible schema early. */
  prepare(tools: readonly ChatTool[]): Promise<void>;
  /** Frees the model and its context. */
  dispose(): Promise<void>;
}

function positiveInteger(name: string, value: number | undefined, fallback: number): number {
  if (value === undefined) return fallback;
  if (!Number.isInteger(value) || value <= 0)
    throw new LocalModelError('CONFIG', `"${name}" must be a positive integer, got ${value}`);
  return value;
}

function checkOptions(options: LocalChatProviderOptions) {
  const temperature = options.temperature ?? 0;
  if (!Number.isFinite(temperature) || temperature < 0)
    throw new LocalModelError('CONFIG', `"temperature" must be 0 or more, got ${temperature}`);
  return {
    threads: positiveInteger('threads', options.threads, defaultThreads()),
    contextSize: positiveInteger('contextSize', options.contextSize, 2048),
    maxTokens: positiveInteger('maxTokens', options.maxTokens, 96),
    answerMaxLength: positiveInteger(
      'answerMaxLength',
      options.answerMaxLength,
      DEFAULT_ANSWER_MAX_LENGTH,
    ),
    temperature,
  };
}

/**
 * Loads a GGUF model in this process and returns it as a chat provider for `runAgent`. Every
 * reply is generated under a grammar built from the offered tools' JSON Schemas: it is always one
 * tool call whose arguments have the schema's shape and types, or an answer that ends the run.
 * Rejects with a LocalModelError: MODEL_MISSING or MODEL_INVALID at once for a bad file, CONFIG
 * for a bad option.
 */
export async function createLocalChatProvider(
  options: LocalChatProviderOptions = {},
): Promise<LocalChatProvider> {
  const settings = checkOptions(options);
  const modelFile = options.modelFile ?? defaultModelFile(options.env);
  await checkModelFile(modelFile, options.modelFile === undefined);
  // loaded here, not at import: a program that imports this package but runs no model (the `hal`
  // command answering --help) does not load llama.cpp's bindings
  const { getLlama, LlamaChat, LlamaLogLevel: Levels } = await loadNodeLlamaCpp();
  const log = (level: LlamaLogLevel, message: string) => {
    const text = message.trim();
    if (text === '' || options.logger === undefined) return;
    const logger = scoped(options.logger, 'hal:agent-local');
    if (level === Levels.error || level === Levels.fatal)
      logger.error(text, { source: 'llama.cpp' });
    else logger.warn(text, { source: 'llama.cpp' });
  };
  let llama: Llama;
  try {
    llama = await getLlama({
      gpu: options.gpu ?? 'auto',
      build: 'never', // the prebuilt binaries only: never download or compile at run time
      logLevel: Levels.warn,
      logger: log,
    });
  } catch (cause) {
    throw new LocalModelError('CONFIG', `llama.cpp could not be loaded: ${String(cause)}`, {
      cause,
    });
  }
  let model: LlamaModel;
  let context: LlamaContext;
  try {
    model = await llama.loadModel({ modelPath: modelFile });
  } catch (cause) {
    await llama.dispose().catch(() => undefined);
    throw new LocalModelError(
      'MODEL_INVALID',
      `model file ${modelFile} could not be loaded (corrupt or truncated?): ${errorMessage(cause)}`,
      { details: { path: modelFile }, cause },
    );
  }
  try {
    context = await model.createContext({
      contextSize: Math.min(settings.contextSize, model.trainContextSize),
      threads: settings.threads,
    });
  } catch (cause) {
    await model.dispose().catch(() => undefined);
    await llama.dispose().catch(() => undefined);
    throw new LocalModelError(
      'CONFIG',
      `no context could be made for the model: ${String(cause)}`,
      {
        cause,
      },
    );
  }
  const sequence = context.getSequence();
  const chat = new LlamaChat({ contextSequence: sequence });
  const grammars = new Map<string, { tools: ChatTool[]; grammar: LlamaGrammar }>();
  let busy = false;

  const offered = (tools: readonly ChatTool[]): ChatTool[] => {
    const filter = options.offerTools;
    if (filter === undefined) return [...tools];
    const names = new Set(tools.map((t) => t.function.name));
    const unknown = filter.find((name) => !names.has(name));
    if (unknown !== undefined) {
      throw new LocalModelError(
        'CONFIG',
        `"offerTools" names "${unknown}", which is not among the tools (${[...names].join(', ')})`,
      );
    }
    return tools.filter((t) => filter.includes(t.function.name));
  };

  const grammarFor = async (tools: readonly ChatTool[], callsOnly = false) => {
    const key = JSON.stringify([
      callsOnly,
      tools.map((t) => [t.function.name, t.function.parameters]),
    ]);
    const cached = grammars.get(key);
    if (cached !== undefined) return cached;
    const chosen = offered(tools);
    const grammar = await replyGrammar(
      llama,
      replySchema(chosen, settings.answerMaxLength, { answer: !callsOnly }),
    );
    const entry = { tools: chosen, grammar };
    grammars.set(key, entry);
    return entry;
  };

  const complete = async (request: ChatRequest, turn: ChatTurn): Promise<ChatReply> => {
    turn.signal.throwIfAborted();
    if (busy)
      throw new LocalModelError('GENERATION', 'the local model is busy with another request');
    busy = true;
    try {
      // a first reply that must call a tool: no tool result in the conversation yet
      const callsOnly =
        options.callFirst === true && !request.messages.some((m) => m.role === 'tool');
      const { tools, grammar } = await grammarFor(request.tools, callsOnly);
      const first = request.messages[0];
      const system = systemText(first?.role === 'system' ? first.content : '', tools);
      const fitted = fitHistory(
        request.messages,
        system,
        context.contextSize - settings.maxTokens,
        (text) => model.tokenize(text).length,
        // examples name tools: only those of this request's tools are shown
        (options.examples ?? []).filter((e) =>
          e.calls.every((c) => tools.some((t) => t.function.name === c.tool)),
        ),
      );
      if (fitted.droppedMessages > 0) {
        turn.onContextTrimmed({
          droppedMessages: fitted.droppedMessages,
          promptTokens: fitted.promptTokens,
          contextTokens: context.contextSize,
        });
      }
      const inputBefore = sequence.tokenMeter.usedInputTokens;
      const outputBefore = sequence.tokenMeter.usedOutputTokens;
      let response;
      try {
        response = await chat.generateResponse(fitted.history, {
          grammar,
          maxTokens: settings.maxTokens,
          temperature: settings.temperature,
          signal: turn.signal,
          stopOnAbortSignal: false,
          onTextChunk: (text) => turn.onToken(text),
        });
      } catch (cause) {
        turn.signal.throwIfAborted();
        throw new LocalModelError('GENERATION', `generation failed: ${String(cause)}`, { cause });
      }
      turn.signal.throwIfAborted();
      const reply = readReply(
        response.response,
        turn.step,
        response.metadata.stopReason === 'maxTokens',
        settings.answerMaxLength,
      );
      return {
        ...reply,
        usage: {
          promptTokens: sequence.tokenMeter.usedInputTokens - inputBefore,
          completionTokens: sequence.tokenMeter.usedOutputTokens - outputBefore,
        },
      };
    } finally {
      busy = false;
    }
  };

  return {
    name: `local:${basename(modelFile)}`,
    modelFile,
    contextTokens: context.contextSize,
    gpu: llama.gpu,
    prepare: async (tools) => {
      await grammarFor(tools);
      if (options.callFirst === true) await grammarFor(tools, true);
    },
    complete,
    dispose: async () => {
      chat.dispose();
      await context.dispose();
      await model.dispose();
      await llama.dispose();
    },
  };
}
