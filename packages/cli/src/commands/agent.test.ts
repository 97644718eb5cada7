// `hal agent` in-process with the real local model (SmolLM2-135M from hal model pull) on
// the embedded simulator: one short generation per run, on one thread (other test files share
// the cores).
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import type { CapturedIO } from '../testing/capture-io.js';
import { runHal } from '../program.js';

const MODEL_MS = 120_000; // a busy shared CPU can be slow; a quiet one takes seconds
const fast = ['--sim', '--time-scale', '20', '--threads', '1'];

type Line = { type: string; [key: string]: unknown };

describe('hal agent with the local model', () => {
  it(
    'runs the model on the simulator and prints every event as JSON, then the outcome and pose',
    async () => {
      const io = captureIO();
      const code = await runHal(
        ['--json', 'agent', ...fast, '--max-steps', '1', 'drive forward 10 cm'],
        io,
      );
      expect(code, io.stderr()).toBe(0);
      const lines = io.jsonLines() as Line[];
      const types = lines.map((l) => l.type);
      expect(types[0]).toBe('step_started');
      expect(types).toContain('token');
      expect(types).toContain('usage');
      expect(types.at(-2)).toBe('done');
      const outcome = lines.at(-1)!;
      expect(outcome).toMatchObject({ type: 'outcome', steps: 1 });
      expect(['completed', 'max_steps']).toContain(outcome['reason']);
      expect(outcome['pose']).toMatchObject({ position: { x: expect.any(Number) } });
      const call = lines.find((l) => l.type === 'tool_call' && l['step'] === 1);
      if (call !== undefined) {
        expect(lines.some((l) => l.type === 'tool_result' && l['id'] === call['id'])).toBe(true);
      }
    },
    MODEL_MS,
  );

  it(
    'stops the generation and the robot on Ctrl-C',
    async () => {
      const base = captureIO();
      const io: CapturedIO = {
        ...base,
        // Ctrl-C as soon as the model starts to answer
        out: (text) => {
          base.out(text);
          if (text.includes('"type":"token"')) base.abort();
        },
      };
      const code = await runHal(['--json', 'agent', ...fast, 'drive backward 20 cm'], io);
      expect(code, base.stderr()).toBe(0);
      const lines = base.jsonLines() as Line[];
      expect(lines.at(-1)).toMatchObject({ type: 'outcome', reason: 'aborted' });
      const calls = lines.filter((l) => l.type === 'tool_call').map((l) => l['name']);
      expect(calls).toEqual(['stop']);
      expect(lines.find((l) => l.type === 'tool_result')).toMatchObject({
        name: 'stop',
        isError: false,
      });
    },
    MODEL_MS,
  );

  it(
    'drives to the red box of a world with the skills, which the default model is offered',
    async () => {
      const world = fileURLToPath(
        new URL('../../../../examples/worlds/look.json', import.meta.url),
      );
      const io = captureIO();
      const code = await runHal(
        ['--json', 'agent', ...fast, '--world', world, '--max-steps', '2', 'drive to the red box'],
        io,
      );
      expect(code, io.stderr()).toBe(0);
      const lines = io.jsonLines() as Line[];
      const calls = lines.filter((l) => l.type === 'tool_call');
      expect(calls[0]).toMatchObject({ name: 'go_to', arguments: '{"target":"red box"}' });
      const result = lines.find((l) => l.type === 'tool_result' && l['name'] === 'go_to');
      expect(result?.['text']).toMatch(/^Reached the red box 1: stopped 0\.\d\d m from it/);
      // the 0.3 m box stands at (0.5, 0.2): the robot stops before its near face, not in it
      const pose = lines.at(-1)?.['pose'] as { position: { x: number; y: number } };
      const gap = Math.hypot(
        Math.max(Math.abs(pose.position.x - 0.5) - 0.15, 0),
        Math.max(Math.abs(pose.position.y - 0.2) - 0.15, 0),
      );
      expect(gap).toBeLessThanOrEqual(0.25);
      expect(gap).toBeGreaterThan(0.05);
    },
    MODEL_MS,
  );

  it('fails at once for a model file that is not there, saying so', async () => {
    const io = captureIO();
    const code = await runHal(['agent', '--model-file', '/nonexistent/m.gguf', 'go'], io);
    expect(code).toBe(1);
    expect(io.stderr()).toMatch(/MODEL_MISSING: model file \/nonexistent\/m\.gguf not found/);
    expect(io.stdout()).toBe('');
  });

  it.each([
    [['--model', 'm', 'go'], /--base-url/],
    [['--base-url', 'http://127.0.0.1:1/v1', '--model-file', 'x.gguf', 'go'], /not both/],
    [['--base-url', 'http://127.0.0.1:1/v1', 'go'], /--model <name>/],
    [['--tools', ',', 'go'], /--tools/],
    [['--tools', 'skills,move', 'go'], /is a profile/],
    [['--world', 'w.json', '--udp', '127.0.0.1:9', 'go'], /--world .* needs --sim/],
  ])('refuses %j before loading anything', async (args, message) => {
    const io = captureIO();
    expect(await runHal(['agent', ...args], io)).toBe(2);
    expect(io.stderr()).toMatch(message);
  });
});
