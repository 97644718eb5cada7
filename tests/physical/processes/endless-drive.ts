// A host that connects PhysicalHAL to the robot at 127.0.0.1:PORT over UDP, starts an endless
// `drive` and then only keeps its session alive (heartbeats), until it is ended. It prints
// {"event":"driving",...} once the robot has accepted the drive. On SIGTERM it shuts down as a
// well-behaved program does: `hal.cleanup()` (which stops the motors), then exit. SIGKILL gives
// it no such chance.
import { PhysicalHAL } from '@hal/physical';

const port = Number(process.argv[2]);
const hal = new PhysicalHAL({
  mode: 'physical',
  deviceId: 'cube-endless-drive',
  connection: { type: 'wifi', host: '127.0.0.1', udpPort: port },
});
process.once('SIGTERM', () => {
  void hal.cleanup().finally(() => process.exit(0));
});
await hal.initialize();
const result = await hal.locomotion.drive(100, 100);
process.stdout.write(
  `${JSON.stringify({ event: 'driving', success: result.success, data: result.data, error: result.error })}\n`,
);
// the session's heartbeat timer keeps this process running; nothing else to do
