// The alternative beside the gateway in nats-spec.bench.ts: the least a Node program on NATS does.
// It connects with nats.js, answers every request on `bench.echo` with the request's bytes, and
// publishes one message on `bench.echo.up` once it is ready (its "capability announcement").
import { connect } from '@nats-io/transport-node';

const url = process.argv[2];
if (url === undefined) {
  process.stderr.write('usage: nats-echo.ts <nats-url>\n');
  process.exit(2);
}
const nc = await connect({ servers: url });
nc.subscribe('bench.echo', {
  callback: (_error, msg) => {
    msg.respond(msg.data);
  },
});
await nc.flush();
nc.publish('bench.echo.up', new TextEncoder().encode('{}'));
await nc.flush();
process.stdin.resume();
process.stdin.on('end', () => void nc.close().then(() => process.exit(0)));
