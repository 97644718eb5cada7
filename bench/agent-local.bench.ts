// The local model through the agent beside node-llama-cpp's own generation: SmolLM2-135M (the
// file bash scripts/setup.sh caches) on two CPU threads, the same prompt, grammar, token limit and
// greedy decoding. Interleaved: each round makes one agent request (runAgent, one step, on the
// simulator) and one direct LlamaChat.generateResponse, so load on the machine falls on both
// alike. Reports generated tokens per second of each and their ratio (the agent's overhead), the
// time from runAgent's start to the first tool call, the model's load time, and the process's
// resident memory with the model loaded.
import { runAgent } from '@hal/agent';
import type { AgentEvent } from '@hal/agent';
import {
  createLocalChatProvider,
  defaultModelFile,
  LOCAL_SYSTEM_PROMPT,
  SMALL_MODEL_TOOLS,
  systemText,
} from '@hal/agent-local';
import { replyGrammar, replySchema } from '@hal/agent-local/grammar';
import { SimulationHAL, World } from '@hal/simulation';
import { createToolExecutor, halTools, toOpenAITools } from '@hal/tools';
import { getLlama, LlamaChat, LlamaLogLevel } from 'node-llama-cpp';
import { percentile, reportFigure } from './report/figures.js';

const ROUNDS = Number(process.env['AGENT_LOCAL_ROUNDS'] ?? 8);
const WARMUP = 1;
const THREADS = 2;
const MAX_TOKENS = 48;
const GOAL = 'drive forward 10 cm';
const mb = (bytes: number) => Math.round(bytes / 1e5) / 10;

const rssBefore = process.memoryUsage().rss;
const loadStart = performance.now();
const provider = await createLocalChatProvider({
  threads: THREADS,
  gpu: false,
  offerTools: SMALL_MODEL_TOOLS,
  maxTokens: MAX_TOKENS,
});
const loadMs = performance.now() - loadStart;
const rssLoaded = process.memoryUsage().rss;

// node-llama-cpp on its own: its own model instance and context, the same settings
const llama = await getLlama({ gpu: false, build: 'never', logLevel: LlamaLogLevel.error });
const model = await llama.loadModel({ modelPath: defaultModelFile() });
const context = await model.createContext({
  contextSize: provider.contextTokens,
  threads: THREADS,
});
const sequence = context.getSequence();
const chat = new LlamaChat({ contextSequence: sequence });

const hal = new SimulationHAL({ world: new World({ map: 'empty' }) });
await hal.initialize();
const tools = halTools(hal);
const executor = createToolExecutor(hal, { tools });
const offered = toOpenAITools(tools).filter((t) => SMALL_MODEL_TOOLS.includes(t.function.name));
const grammar = await replyGrammar(llama, replySchema(offered));
const history = [
  { type: 'system' as const, text: systemText(LOCAL_SYSTEM_PROMPT, offered) },
  { type: 'user' as const, text: GOAL },
  { type: 'model' as const, response: [] },
];

async function agentRound() {
  const started = performance.now();
  let firstCallMs: number | undefined;
  let usage: Extract<AgentEvent, { type: 'usage' }> | undefined;
  await runAgent({
    goal: GOAL,
    executor,
    provider,
    systemPrompt: LOCAL_SYSTEM_PROMPT,
    caps: { maxSteps: 1 },
    onEvent: (event) => {
      if (event.type === 'usage') usage = event;
      if (event.type === 'tool_call' && firstCallMs === undefined)
        firstCallMs = performance.now() - started;
    },
  });
  if (usage?.completionTokens === undefined) throw new Error('the agent reported no token counts');
  return { ms: usage.durationMs, tokens: usage.completionTokens, firstCallMs };
}

async function directRound() {
  const meter = sequence.tokenMeter;
  const before = meter.usedOutputTokens;
  const started = performance.now();
  await chat.generateResponse(history, { grammar, maxTokens: MAX_TOKENS, temperature: 0 });
  return { ms: performance.now() - started, tokens: meter.usedOutputTokens - before };
}

const agentRate: number[] = [];
const directRate: number[] = [];
const ratios: number[] = [];
const firstCalls: number[] = [];
for (let i = 0; i < WARMUP + ROUNDS; i += 1) {
  const agent = await agentRound();
  const direct = await directRound();
  if (i < WARMUP) continue;
  const a = (agent.tokens * 1000) / agent.ms;
  const d = (direct.tokens * 1000) / direct.ms;
  agentRate.push(a);
  directRate.push(d);
  ratios.push(d / a);
  if (agent.firstCallMs !== undefined) firstCalls.push(agent.firstCallMs);
}

const agent50 = percentile(agentRate, 50);
const direct50 = percentile(directRate, 50);
const ratio50 = percentile(ratios, 50);
console.log(
  `SmolLM2-135M Q4_1, ${THREADS} threads, "${GOAL}", ${ROUNDS} interleaved rounds (median):`,
);
console.log(`  through the agent:     ${agent50.toFixed(1)} tokens/s`);
console.log(`  node-llama-cpp alone:  ${direct50.toFixed(1)} tokens/s`);
console.log(`  agent overhead:        ${ratio50.toFixed(2)}x (time per token, agent / direct)`);
if (firstCalls.length > 0)
  console.log(
    `  first tool call:       ${percentile(firstCalls, 50).toFixed(0)} ms after runAgent starts (${firstCalls.length} of ${ROUNDS} rounds called a tool)`,
  );
console.log(
  `  model load:            ${loadMs.toFixed(0)} ms; resident memory ${mb(rssBefore)} MB before, ${mb(rssLoaded)} MB with the model loaded`,
);
reportFigure({
  bench: 'agent-local',
  name: 'generation through the agent (median)',
  value: Math.round(agent50 * 10) / 10,
  unit: 'tokens/s',
  better: 'higher',
  alternative: { name: 'node-llama-cpp alone', value: Math.round(direct50 * 10) / 10 },
});
reportFigure({
  bench: 'agent-local',
  name: 'agent overhead per token (median ratio)',
  value: Math.round(ratio50 * 100) / 100,
  unit: 'x',
  better: 'lower',
});
if (firstCalls.length > 0)
  reportFigure({
    bench: 'agent-local',
    name: 'time to the first tool call (median)',
    value: Math.round(percentile(firstCalls, 50)),
    unit: 'ms',
    better: 'lower',
  });
reportFigure({
  bench: 'agent-local',
  name: 'resident memory with the model loaded',
  value: mb(rssLoaded),
  unit: 'MB',
  better: 'lower',
});

chat.dispose();
await context.dispose();
await model.dispose();
await llama.dispose();
await provider.dispose();
await hal.cleanup();
