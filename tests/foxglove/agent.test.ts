// `hal agent --foxglove`: a viewer watches the agent's run (the fake endpoint model over real
// HTTP, the embedded simulator) and its teleop is held to the agent's own leash.
import { runHal } from '@hal/cli';
import { afterEach, describe, expect, it } from 'vitest';
import { captureIO } from '../cli/capture-io.js';
import { startFakeOpenAIServer } from '../helpers/fake-openai-server.js';
import type { FakeOpenAIServer } from '../helpers/fake-openai-server.js';
import { connectViewer } from './viewer.js';

let model: FakeOpenAIServer | undefined;
afterEach(async () => {
  await model?.close();
  model = undefined;
});

describe('hal agent --foxglove', () => {
  it('shows the run to a viewer, whose teleop meets the agent leash', async () => {
    // the model thinks for as long as the test needs: the run ends with Ctrl-C
    model = await startFakeOpenAIServer([{ hang: true }]);
    const io = captureIO({});
    const run = runHal(
      [
        '--json',
        'agent',
        '--sim',
        '--base-url',
        model.baseUrl,
        '--model',
        'fake',
        '--max-speed',
        '0.01',
        '--foxglove',
        '0',
        'wait',
      ],
      io,
    );
    const url = await new Promise<string>((resolve, reject) => {
      const timer = setInterval(() => {
        const match = /"event":"foxglove","url":"(ws:\/\/[^"]+)"/.exec(io.stderr());
        if (match !== null) {
          clearInterval(timer);
          resolve(match[1]!);
        }
      }, 20);
      void run.then((code) => {
        clearInterval(timer);
        reject(new Error(`hal agent ended (${code}) before serving: ${io.stderr()}`));
      });
    });
    const viewer = await connectViewer(url);
    try {
      // the agent's perception (the simulator has a camera) is on the view too
      expect(viewer.channels.map((c) => c.topic)).toContain('/perception/detections');
      await viewer.subscribe('/hal/pose');
      await viewer.until(() => viewer.on('/hal/pose').length >= 2);
      const publish = viewer.publisher('/cmd_vel', 'geometry_msgs/Twist');
      publish({ linear: { x: 0.04, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } });
      await viewer.until(() => viewer.statuses.some((s) => s.message.includes('LEASH_SPEED')));
    } finally {
      viewer.close();
    }
    io.abort();
    await run;
    expect(io.stderr()).toMatch(/teleop from viewer-1 refused \(LEASH_SPEED\)/);
  });
});
