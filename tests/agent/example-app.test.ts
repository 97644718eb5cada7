// examples/llm-agent run as a user runs it, in its own Node process: against the fake endpoint,
// driving the simulator (the default) and the emulated robot over UDP (HAL_UDP_HOST).
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { distanceToSteps } from '@hal/kinematics';
import { afterAll, describe, expect, it } from 'vitest';
import { freePort } from '../nats/nats-server.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { call, serve } from './fixtures.js';

afterAll(stopAllEmulators);

const APP = fileURLToPath(new URL('../../examples/llm-agent/', import.meta.url));

/** Runs the app with `env` and the goal; kills it after `timeoutMs`. */
function runApp(
  env: Record<string, string>,
  goal: string,
  timeoutMs = 60_000,
): Promise<{ code: number | string; stdout: string; stderr: string }> {
  return new Promise((resolve) => {
    const child = spawn(
      process.execPath,
      ['--conditions=@hal/source', '--import', 'tsx', 'main.ts', goal],
      // Only what the app needs: no endpoint or robot settings leak in from the test's shell.
      {
        cwd: APP,
        env: { PATH: process.env['PATH'] ?? '', ...env },
        stdio: ['ignore', 'pipe', 'pipe'],
      },
    );
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (chunk: Buffer) => (stdout += chunk.toString()));
    child.stderr.on('data', (chunk: Buffer) => (stderr += chunk.toString()));
    const timer = setTimeout(() => child.kill('SIGKILL'), timeoutMs);
    child.once('exit', (code, signal) => {
      clearTimeout(timer);
      resolve({ code: code ?? signal ?? 'unknown', stdout, stderr });
    });
  });
}

describe('examples/llm-agent', () => {
  it('drives the simulator to the goal the model plans, printing each call and result', async () => {
    const s = await serve([
      { content: 'First I check where I am.', toolCalls: [call('get_pose')] },
      { content: null, toolCalls: [call('move_forward', { distanceCm: 25 })] },
      { content: 'I drove 25 cm forward.' },
    ]);
    const run = await runApp(
      { OPENAI_BASE_URL: s.baseUrl, OPENAI_MODEL: 'fake-model', OPENAI_API_KEY: 'sk-app' },
      'Drive 25 cm forward.',
    );
    expect(run.stderr).toBe('');
    expect(run.code).toBe(0);
    expect(run.stdout).toContain('robot: simulator, map "obstacles"');
    expect(run.stdout).toContain('call move_forward {"distanceCm":25}');
    expect(run.stdout).toMatch(/result move_forward: \{"success":true/);
    expect(run.stdout).toContain('done: completed after 3 steps');
    // The robot started at x -1.8 m facing +x.
    expect(run.stdout).toContain('pose: x -1.550 m, y 0.000 m');
    expect(s.requests[0]?.headers['authorization']).toBe('Bearer sk-app');
    expect(s.requests[0]?.body.messages?.[1]).toMatchObject({ content: 'Drive 25 cm forward.' });
  });

  it('runs the local model when no endpoint is set, and moves or reports what it chose', async () => {
    // HOME (or XDG_CACHE_HOME) locates the model bash scripts/setup.sh cached
    const cache = {
      HOME: process.env['HOME'] ?? '',
      ...(process.env['XDG_CACHE_HOME'] ? { XDG_CACHE_HOME: process.env['XDG_CACHE_HOME'] } : {}),
    };
    const run = await runApp(cache, 'drive forward 10 cm', 120_000);
    expect(run.code, run.stderr).toBe(0);
    expect(run.stdout).toMatch(/model: .*SmolLM2-135M-Instruct\.Q4_1\.gguf \(in this process\)/);
    expect(run.stdout).toMatch(/done: (completed|max_steps) after 1 step,/);
    expect(run.stdout).toMatch(/pose: x -?\d/);
  }, 150_000); // the app's own bound is 120 s: loading the model and one generation on a busy CPU

  it('refuses a missing model file at once, naming it', async () => {
    const run = await runApp({ HAL_MODEL_FILE: '/nonexistent/model.gguf' }, 'Anything.');
    expect(run.code).not.toBe(0);
    expect(run.stderr).toContain('model file /nonexistent/model.gguf not found');
  });

  it('refuses the hosted default endpoint without a key, naming the URL and both variables', async () => {
    const run = await runApp({ OPENAI_MODEL: 'gpt-4o-mini' }, 'Anything.');
    expect(run.code).toBe(2);
    expect(run.stdout).toBe('');
    expect(run.stderr).toContain('https://api.openai.com/v1');
    expect(run.stderr).toMatch(/OPENAI_BASE_URL is not.*OPENAI_API_KEY is not set/s);
  });

  it('names the endpoint URL and the cause when nothing listens there', async () => {
    const port = await freePort();
    const run = await runApp(
      { OPENAI_BASE_URL: `http://127.0.0.1:${port}/v1`, OPENAI_MODEL: 'm', AGENT_MAX_STEPS: '1' },
      'Anything.',
    );
    expect(run.code).toBe(1);
    expect(run.stdout).toContain(`endpoint: http://127.0.0.1:${port}/v1 (model m, no key)`);
    expect(run.stdout).toContain(
      `endpoint error NETWORK: request to http://127.0.0.1:${port}/v1/chat/completions failed: fetch failed (connect ECONNREFUSED 127.0.0.1:${port})`,
    );
  });

  it('drives the emulated robot over UDP when HAL_UDP_HOST is set', async () => {
    const emulator = await startEmulator({ pty: false });
    try {
      const s = await serve([
        { content: null, toolCalls: [call('move_forward', { distanceCm: 10 })] },
        { content: 'Moved 10 cm.' },
      ]);
      const run = await runApp(
        {
          OPENAI_BASE_URL: s.baseUrl,
          OPENAI_MODEL: 'fake-model',
          HAL_UDP_HOST: '127.0.0.1',
          HAL_UDP_PORT: String(emulator.udpPort),
        },
        'Move 10 cm forward.',
      );
      expect(run.stderr).toBe('');
      expect(run.code).toBe(0);
      expect(run.stdout).toContain(`robot: robot at udp://127.0.0.1:${emulator.udpPort}`);
      expect(run.stdout).toContain('pose: x 0.100 m');
      // The robot itself moved: its firmware core reports one finished 10 cm move.
      const moves = await emulator.waitForCount((e) => e.event === 'move_finished', 1);
      expect(moves).toHaveLength(1);
      const steps = distanceToSteps(10);
      expect(moves[0]).toMatchObject({ left_steps: steps, right_steps: steps });
    } finally {
      await emulator.stop();
    }
  });
});
