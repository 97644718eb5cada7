// The size of a recording per minute of a typical agent run, with and without camera frames. Two
// agent runs at once, in the same process for the same wall-clock time, each on its own simulated
// robot (real-time clock) recorded with `hal agent --record`'s defaults (pose every 100 ms, zstd
// chunks): the @hal/agent loop with a scripted model that takes TURN_MS a turn (a small local
// model's pace; an assumption, said in the figure) and drives a square, 5 cm ahead then a 90
// degree turn. The looking agent also calls capture_frame every turn (a 320x240 JPEG from the
// simulator's camera). `--seconds N` (or RECORDER_SIZE_SECONDS) sets how long (default 60); the
// figures are scaled to a minute and say how long they were measured.
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { runAgent } from '@hal/agent';
import type { ChatProvider, ChatReply, ChatRequest } from '@hal/agent';
import { AGENT_EVENT, McapRecorder, readRecordingFile, recordHal, TOPICS } from '@hal/recorder';
import type { RecorderStats } from '@hal/recorder';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor, halTools } from '@hal/tools';
import { delay } from '@hal/types';
import { reportFigure } from './report/figures.js';

const { values } = parseArgs({ options: { seconds: { type: 'string' } } });
const SECONDS = Number(values.seconds ?? process.env['RECORDER_SIZE_SECONDS'] ?? 60);
if (!(SECONDS > 0)) throw new Error(`--seconds must be a positive number, got ${values.seconds}`);
const TURN_MS = 1500;

/** A model that answers after TURN_MS: a motion each turn (and a look, when it looks). */
function scriptedModel(looks: boolean): ChatProvider {
  let turn = 0;
  return {
    name: looks ? 'scripted:looking' : 'scripted:blind',
    async complete(_request: ChatRequest, chat): Promise<ChatReply> {
      await delay(TURN_MS);
      if (chat.signal.aborted) throw chat.signal.reason;
      turn += 1;
      const motion =
        turn % 2 === 1
          ? { name: 'move_forward', arguments: JSON.stringify({ distanceCm: 5 }) }
          : { name: 'rotate', arguments: JSON.stringify({ direction: 'left', degrees: 90 }) };
      const calls = looks ? [motion, { name: 'capture_frame', arguments: '{}' }] : [motion];
      return {
        text: '',
        refusal: undefined,
        toolCalls: calls.map((c, i) => ({
          id: `call_${turn}_${i}`,
          type: 'function' as const,
          function: c,
        })),
        usage: { promptTokens: 900 + turn * 60, completionTokens: 24 },
      };
    },
  };
}

async function agentRun(
  looks: boolean,
  file: string,
  signal: AbortSignal,
): Promise<{ stats: RecorderStats; calls: number; frames: number }> {
  const recorder = await McapRecorder.toFile(file);
  recorder.channel(TOPICS.agent, AGENT_EVENT);
  const sim = new SimulationHAL({ clock: 'realtime', realtimeSpeed: 1, deviceId: 'agent-bench' });
  const hal = recordHal(sim, recorder);
  await hal.initialize();
  const tools = halTools(hal, {
    include: ['move_forward', 'rotate', 'stop', ...(looks ? ['capture_frame'] : [])],
  });
  await runAgent({
    goal: 'drive a square',
    executor: createToolExecutor(hal, { tools }),
    provider: scriptedModel(looks),
    caps: { maxSteps: 10_000, maxMs: SECONDS * 1000 + 60_000 },
    signal,
    onEvent: (event) => recorder.write(TOPICS.agent, event),
  });
  await hal.cleanup();
  const stats = await recorder.close();
  const recording = await readRecordingFile(file);
  return {
    stats,
    calls: recording.channels.get(TOPICS.calls)?.messageCount ?? 0,
    frames: recording.channels.get(TOPICS.camera)?.messageCount ?? 0,
  };
}

const dir = mkdtempSync(join(tmpdir(), 'hal-bench-recorder-size-'));
try {
  const stop = AbortSignal.timeout(SECONDS * 1000);
  const files = { blind: join(dir, 'blind.mcap'), looking: join(dir, 'looking.mcap') };
  const started = performance.now();
  const [blind, looking] = await Promise.all([
    agentRun(false, files.blind, stop),
    agentRun(true, files.looking, stop),
  ]);
  const minutes = (performance.now() - started) / 60_000;
  const perMinute = (file: string) => statSync(file).size / minutes;
  const kib = (bytes: number) => `${(bytes / 1024).toFixed(0)} KiB`;
  console.log(
    `recorder: two agent runs side by side for ${SECONDS} s (a model turn every ${TURN_MS} ms, pose every 100 ms)`,
  );
  console.log(
    `  without camera frames: ${kib(perMinute(files.blind))}/min (${blind.calls} calls, ${blind.stats.written} messages, ${blind.stats.dropped} dropped)`,
  );
  console.log(
    `  with a frame a turn:   ${kib(perMinute(files.looking))}/min (${looking.calls} calls, ${looking.frames} frames, ${looking.stats.written} messages, ${looking.stats.dropped} dropped)`,
  );
  const note = `measured over ${SECONDS} s and scaled to a minute; the simulator (real-time), a scripted model answering every ${TURN_MS} ms (assumed pace), recordHal defaults`;
  reportFigure({
    bench: 'recorder-size',
    name: 'recording size per minute of an agent run, with a camera frame a turn',
    value: perMinute(files.looking) / 1024,
    unit: 'KiB/min',
    better: 'lower',
    alternative: {
      name: 'the same run without camera frames',
      value: perMinute(files.blind) / 1024,
    },
    note: `${looking.frames} frames of 320x240 JPEG; ${note}`,
  });
} finally {
  rmSync(dir, { recursive: true, force: true });
}
