// Holds ports on the machine's 127.0.0.1 the way its own services would (the README's
// nats-server on 4222, a `hal serve` on 8765, a cube emulator on UDP 4210, ...), for a test that
// shows it does not need them: TCP listeners and UDP sockets bound until released. A port that
// something else already holds is left to it (it is just as taken).
import { createSocket } from 'node:dgram';
import type { Socket } from 'node:dgram';
import { createServer } from 'node:net';
import type { Server } from 'node:net';

/** What was held: the ports this process bound, by protocol, and a release of them all. */
export interface HeldPorts {
  tcp: number[];
  udp: number[];
  release(): Promise<void>;
}

function holdTcp(port: number): Promise<Server | undefined> {
  return new Promise((resolve, reject) => {
    const server = createServer((socket) => socket.destroy());
    server.once('error', (error: NodeJS.ErrnoException) =>
      error.code === 'EADDRINUSE' ? resolve(undefined) : reject(error),
    );
    server.listen({ port, host: '127.0.0.1', exclusive: true }, () => resolve(server));
  });
}

function holdUdp(port: number): Promise<Socket | undefined> {
  return new Promise((resolve, reject) => {
    const socket = createSocket('udp4');
    socket.once('error', (error: NodeJS.ErrnoException) =>
      error.code === 'EADDRINUSE' ? resolve(undefined) : reject(error),
    );
    socket.bind({ port, address: '127.0.0.1', exclusive: true }, () => resolve(socket));
  });
}

/** Binds each of `ports` on 127.0.0.1, TCP and UDP, where nothing holds it yet. */
export async function holdPorts(ports: readonly number[]): Promise<HeldPorts> {
  const servers: Server[] = [];
  const sockets: Socket[] = [];
  const release = async () => {
    await Promise.all(servers.map((s) => new Promise<void>((resolve) => s.close(() => resolve()))));
    await Promise.all(sockets.map((s) => new Promise<void>((resolve) => s.close(() => resolve()))));
  };
  try {
    for (const port of ports) {
      const server = await holdTcp(port);
      if (server !== undefined) servers.push(server);
      const socket = await holdUdp(port);
      if (socket !== undefined) sockets.push(socket);
    }
  } catch (error) {
    await release();
    throw error;
  }
  const portOf = (address: unknown) =>
    typeof address === 'object' && address !== null && 'port' in address ? Number(address.port) : 0;
  return {
    tcp: servers.map((s) => portOf(s.address())),
    udp: sockets.map((s) => s.address().port),
    release,
  };
}

/** Those of `ports` that something holds on 127.0.0.1 (TCP), in the order given. */
export async function takenPorts(ports: readonly number[]): Promise<number[]> {
  const taken: number[] = [];
  for (const port of ports) {
    const server = await holdTcp(port);
    if (server === undefined) taken.push(port);
    else await new Promise<void>((resolve) => server.close(() => resolve()));
  }
  return taken;
}
