// A process that records a simulated robot driving in circles until it is killed: the far end of
// the SIGKILL test. It prints one JSON line when it starts, with the file it writes.
import { McapRecorder, recordHal } from '@hal/recorder';
import { SimulationHAL } from '@hal/simulation';

const path = process.argv[2];
if (path === undefined) throw new Error('usage: recording-child.ts FILE');
const recorder = await McapRecorder.toFile(path, { chunkSize: 4096 });
const hal = recordHal(
  new SimulationHAL({ deviceId: 'sim-killed', clock: 'realtime', realtimeSpeed: 20 }),
  recorder,
  {
    posePeriodMs: 10,
  },
);
await hal.initialize();
process.stdout.write(`${JSON.stringify({ event: 'recording', path })}\n`);
for (;;) {
  await hal.locomotion.moveForward(2);
  await hal.locomotion.rotate('left', 30);
  hal.communication.log('one more lap', 'info');
}
