// An LLM agent drives the robot: the goal from the command line, the model from the environment.
//
//   OPENAI_BASE_URL=http://127.0.0.1:11434/v1 OPENAI_MODEL=qwen2.5vl:7b \
//     pnpm --filter @hal/example-llm-agent start "Drive 30 cm forward, then turn left"
//
// Without OPENAI_MODEL it runs a local GGUF model in the process: HAL_MODEL_FILE, or the
// SmolLM2-135M file `bash scripts/setup.sh` caches (offered four tools, one step by default).
// The simulator by default; HAL_UDP_HOST (HAL_UDP_PORT, HAL_KEY) or HAL_SERIAL_PORT for a robot.
// Ctrl-C stops the run and the robot.
import { runAgent } from '@hal/agent';
import type { RunAgentOptions } from '@hal/agent';
import { createLocalChatProvider, LOCAL_SYSTEM_PROMPT, SMALL_MODEL_TOOLS } from '@hal/agent-local';
import type { LocalChatProvider } from '@hal/agent-local';
import { createToolExecutor } from '@hal/tools';
import { describeEvent } from './print.js';
import { robotFromEnv } from './robot.js';

const env = process.env;
const goal = process.argv.slice(2).join(' ') || 'Tell me where you are and what you see.';
const model = env['OPENAI_MODEL'];
const modelFile = env['HAL_MODEL_FILE'];
let local: LocalChatProvider | undefined;
if (model === undefined || model === '') {
  // a missing or corrupt model file fails here, before the robot is touched
  local = await createLocalChatProvider({
    ...(modelFile ? { modelFile } : { offerTools: SMALL_MODEL_TOOLS }),
  });
  console.log(`model: ${local.modelFile} (in this process)`);
}
const HOSTED = 'https://api.openai.com/v1';
const baseUrl = env['OPENAI_BASE_URL'] || HOSTED;
const apiKey = env['OPENAI_API_KEY'] || undefined;
// The hosted default answers nothing without a key: say so now, not after a failed request.
if (local === undefined && baseUrl === HOSTED && apiKey === undefined) {
  console.error(
    `OPENAI_MODEL is set but OPENAI_BASE_URL is not, so the endpoint would be the hosted ${HOSTED}, ` +
      'and OPENAI_API_KEY is not set. Set OPENAI_BASE_URL to your endpoint ' +
      '(e.g. http://127.0.0.1:11434/v1 for a local server), or OPENAI_API_KEY for the hosted one.',
  );
  process.exit(2);
}
const smallModel = local !== undefined && !modelFile;

const { hal, label } = robotFromEnv(env);
await hal.initialize();
console.log(`robot: ${label}`);
if (local === undefined) {
  console.log(
    `endpoint: ${baseUrl} (model ${model}, ${apiKey === undefined ? 'no key' : 'with a key'})`,
  );
}
console.log(`goal: ${goal}`);

const controller = new AbortController();
process.once('SIGINT', () => controller.abort());

// Keep the model on a leash: short moves, slow enough to watch.
const executor = createToolExecutor(hal, { leash: { maxDistanceM: 1, maxSpeedMPerS: 0.05 } });
const outcome = await runAgent({
  goal,
  executor,
  ...modelOptions(),
  // the small default model never says it is done: one step, unless AGENT_MAX_STEPS says more
  caps: { maxSteps: Number(env['AGENT_MAX_STEPS'] ?? (smallModel ? 1 : 20)), maxMs: 5 * 60_000 },
  signal: controller.signal,
  onEvent: (event) => {
    const line = describeEvent(event);
    if (line !== undefined) console.log(line);
  },
});

const pose = await hal.locomotion.getPose();
console.log(
  `pose: x ${pose.position.x.toFixed(3)} m, y ${pose.position.y.toFixed(3)} m, ` +
    `yaw ${((pose.rotation.yaw * 180) / Math.PI).toFixed(1)} deg`,
);
if (outcome.text !== '') console.log(`model: ${outcome.text}`);
await local?.dispose();
await hal.cleanup();
process.exitCode = outcome.reason === 'completed' || outcome.reason === 'max_steps' ? 0 : 1;

function modelOptions(): Pick<RunAgentOptions, 'endpoint' | 'provider' | 'systemPrompt'> {
  if (local !== undefined)
    return { provider: local, ...(smallModel ? { systemPrompt: LOCAL_SYSTEM_PROMPT } : {}) };
  return {
    endpoint: { baseUrl, model: model ?? '', ...(apiKey === undefined ? {} : { apiKey }) },
  };
}
