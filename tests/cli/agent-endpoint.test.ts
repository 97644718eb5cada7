// `hal agent --base-url`: the same command on an OpenAI-compatible endpoint (the fake one, over
// real HTTP on 127.0.0.1), driving the embedded simulator; no local model is loaded.
import { runHal } from '@hal/cli';
import { distanceToSteps } from '@hal/kinematics';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import type { FakeOpenAIServer, ScriptedReply } from '../helpers/fake-openai-server.js';
import { captureIO } from './capture-io.js';

afterAll(stopAllEmulators);

let server: FakeOpenAIServer | undefined;
afterEach(async () => {
  await server?.close();
  server = undefined;
});

async function serve(script: ScriptedReply[]): Promise<FakeOpenAIServer> {
  server = await startFakeOpenAIServer(script);
  return server;
}

type Line = { type: string; [key: string]: unknown };
const fast = ['--sim', '--time-scale', '20'];

describe('hal agent --base-url', () => {
  it('drives the simulator with the endpoint model, its key from $OPENAI_API_KEY', async () => {
    const s = await serve([
      {
        content: null,
        toolCalls: [{ name: 'move_forward', arguments: JSON.stringify({ distanceCm: 10 }) }],
      },
      { content: 'I drove 10 cm forward.' },
    ]);
    const io = captureIO({ OPENAI_API_KEY: 'sk-test' });
    const code = await runHal(
      ['--json', 'agent', ...fast, '--base-url', s.baseUrl, '--model', 'fake', 'drive 10 cm'],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const lines = io.jsonLines() as Line[];
    expect(lines.find((l) => l.type === 'tool_result')).toMatchObject({
      name: 'move_forward',
      isError: false,
    });
    expect(lines.filter((l) => l.type === 'usage')).toHaveLength(2);
    const outcome = lines.at(-1)!;
    expect(outcome).toMatchObject({ type: 'outcome', reason: 'completed', steps: 2 });
    expect(outcome['text']).toBe('I drove 10 cm forward.');
    expect((outcome['pose'] as { position: { x: number } }).position.x).toBeCloseTo(0.1, 2);
    expect(s.requests[0]?.headers['authorization']).toBe('Bearer sk-test');
    expect(s.requests[0]?.body.model).toBe('fake');
    // every tool by default
    expect(s.requests[0]?.body.tools?.length).toBeGreaterThan(10);
  });

  it('offers only the --tools it names, and stop, which the loop keeps to end a run with', async () => {
    const s = await serve([{ content: 'Nothing to do.' }]);
    const io = captureIO({ OPENAI_MODEL: 'from-env' });
    const code = await runHal(
      ['agent', ...fast, '--base-url', s.baseUrl, '--tools', 'get_pose', 'where are you?'],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    expect(s.requests[0]?.body.model).toBe('from-env');
    expect(s.requests[0]?.body.tools?.map((t) => t.function.name).sort()).toEqual([
      'get_pose',
      'stop',
    ]);
    expect(s.requests[0]?.headers['authorization']).toBeUndefined();
    expect(io.stdout()).toContain('done: completed after 1 step');
    expect(io.stdout()).toContain('model: Nothing to do.');
  });

  it('exits 1 when the endpoint fails for good, naming the failure', async () => {
    const s = await serve([{ status: 401, body: 'bad key' }]);
    const io = captureIO({});
    const code = await runHal(
      ['agent', ...fast, '--base-url', s.baseUrl, '--model', 'm', 'go'],
      io,
    );
    expect(code).toBe(1);
    expect(io.stderr()).toMatch(/hal: FAILED: HTTP: HTTP 401/);
  });

  it('drives the emulated robot over UDP (--udp), which reports one finished 10 cm move', async () => {
    const emulator = await startEmulator({ pty: false });
    try {
      const s = await serve([
        {
          content: null,
          toolCalls: [{ name: 'move_forward', arguments: JSON.stringify({ distanceCm: 10 }) }],
        },
        { content: 'Moved.' },
      ]);
      const io = captureIO({});
      const code = await runHal(
        [
          '--json',
          'agent',
          '--udp',
          `127.0.0.1:${emulator.udpPort}`,
          '--base-url',
          s.baseUrl,
          '--model',
          'fake',
          'drive 10 cm',
        ],
        io,
      );
      expect(code, io.stderr()).toBe(0);
      expect((io.jsonLines() as Line[]).at(-1)).toMatchObject({ reason: 'completed' });
      const moves = await emulator.waitForCount((e) => e.event === 'move_finished', 1);
      expect(moves).toHaveLength(1);
      const steps = distanceToSteps(10);
      expect(moves[0]).toMatchObject({ left_steps: steps, right_steps: steps });
    } finally {
      await emulator.stop();
    }
  });
});
