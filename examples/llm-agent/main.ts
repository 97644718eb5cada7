// An LLM agent drives the robot: the goal from the command line, the model from the environment.
//
//   OPENAI_BASE_URL=http://127.0.0.1:11434/v1 OPENAI_MODEL=qwen2.5vl:7b \
//     pnpm --filter @hal/example-llm-agent start "Drive 30 cm forward, then turn left"
//
// The simulator by default; HAL_UDP_HOST (HAL_UDP_PORT, HAL_KEY) or HAL_SERIAL_PORT for a robot.
// Ctrl-C stops the run and the robot.
import { runAgent } from '@hal/agent';
import { createToolExecutor } from '@hal/tools';
import { describeEvent } from './print.js';
import { robotFromEnv } from './robot.js';

const env = process.env;
const goal = process.argv.slice(2).join(' ') || 'Tell me where you are and what you see.';
const model = env['OPENAI_MODEL'];
if (model === undefined || model === '') {
  console.error('Set OPENAI_MODEL (and OPENAI_BASE_URL, OPENAI_API_KEY for your endpoint).');
  process.exit(2);
}

const { hal, label } = robotFromEnv(env);
await hal.initialize();
console.log(`robot: ${label}`);
console.log(`goal: ${goal}`);

const controller = new AbortController();
process.once('SIGINT', () => controller.abort());

// Keep the model on a leash: short moves, slow enough to watch.
const executor = createToolExecutor(hal, { leash: { maxDistanceM: 1, maxSpeedMPerS: 0.05 } });
const outcome = await runAgent({
  goal,
  executor,
  endpoint: {
    baseUrl: env['OPENAI_BASE_URL'] ?? 'https://api.openai.com/v1',
    model,
    ...(env['OPENAI_API_KEY'] ? { apiKey: env['OPENAI_API_KEY'] } : {}),
  },
  caps: { maxSteps: Number(env['AGENT_MAX_STEPS'] ?? 20), maxMs: 5 * 60_000 },
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
await hal.cleanup();
process.exitCode = outcome.reason === 'completed' ? 0 : 1;
