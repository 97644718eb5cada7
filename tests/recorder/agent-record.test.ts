// `hal agent --record`: an agent run on the simulator (the model behind the fake OpenAI-compatible
// endpoint, over real HTTP on 127.0.0.1) recorded into MCAP: the robot's calls and pose, and the
// agent's own events (tool calls, results, token usage) on /agent/events.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { readRecordingFile } from '@hal/recorder';
import { afterAll, describe, expect, it } from 'vitest';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import { captureIO } from '../cli/capture-io.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-agent-record-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

describe('hal agent --record', () => {
  it("records the robot's calls and the agent's events of one run", async () => {
    const server = await startFakeOpenAIServer([
      {
        content: null,
        toolCalls: [{ name: 'move_forward', arguments: JSON.stringify({ distanceCm: 10 }) }],
      },
      { content: 'I drove 10 cm forward.' },
    ]);
    const file = join(dir, 'agent.mcap');
    try {
      const io = captureIO({});
      const code = await runHal(
        [
          '--json',
          'agent',
          '--sim',
          '--time-scale',
          '20',
          '--base-url',
          server.baseUrl,
          '--model',
          'fake',
          '--record',
          file,
          'drive 10 cm',
        ],
        io,
      );
      expect(code, io.stderr()).toBe(0);
      expect(io.jsonLines().at(-1)).toMatchObject({
        type: 'outcome',
        reason: 'completed',
        recording: { file, dropped: 0 },
      });
    } finally {
      await server.close();
    }
    const recording = await readRecordingFile(file);
    expect(recording.complete).toBe(true);
    const move = recording.messages
      .filter((m) => m.topic === '/hal/calls')
      .map((m) => m.value as { call: string; args: unknown[]; success: boolean })
      .find((c) => c.call === 'locomotion.moveForward');
    expect(move).toMatchObject({ args: [10], success: true });
    const events = recording.messages
      .filter((m) => m.topic === '/agent/events')
      .map((m) => (m.value as { type: string }).type);
    expect(events).toContain('tool_result');
    expect(events).toContain('usage');
    expect(recording.channels.get('/agent/events')?.schemaName).toBe('hal.AgentEvent');
  });
});
