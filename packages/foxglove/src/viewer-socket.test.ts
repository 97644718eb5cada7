import { EventEmitter } from 'node:events';
import type { WebSocket } from 'ws';
import { describe, expect, it } from 'vitest';
import { ViewerSocket } from './viewer-socket.js';

/** A socket whose send buffer the test sets. */
class FakeSocket extends EventEmitter {
  readonly OPEN = 1;
  readyState = 1;
  bufferedAmount = 0;
  binaryType = 'nodebuffer';
  protocol = 'foxglove.websocket.v1';
  onclose: unknown = null;
  readonly sent: unknown[] = [];
  send(data: unknown): void {
    this.sent.push(data);
  }
  close(): void {
    this.readyState = 3;
  }
}

/** A message on subscription `sub`, as the protocol server frames it. */
function messageData(sub: number, bytes = 10): Uint8Array {
  const frame = new Uint8Array(13 + bytes);
  const view = new DataView(frame.buffer);
  view.setUint8(0, 1);
  view.setUint32(1, sub, true);
  return frame;
}

function viewer(max = 100) {
  const fake = new FakeSocket();
  const firstDrops: string[] = [];
  const topics = new Map([
    [7, '/hal/pose'],
    [8, '/hal/camera'],
  ]);
  const socket = new ViewerSocket(fake as unknown as WebSocket, max, (id) => topics.get(id), {
    firstDrop: (topic) => firstDrops.push(topic),
  });
  // the viewer subscribes: subscription 1 to the pose's channel, 2 to the camera's
  const subscribe = JSON.stringify({
    op: 'subscribe',
    subscriptions: [
      { id: 1, channelId: 7 },
      { id: 2, channelId: 8 },
    ],
  });
  fake.emit('message', Buffer.from(subscribe), false);
  return { fake, socket, firstDrops };
}

describe('ViewerSocket', () => {
  it('sends while the queue has room, and drops beyond it, counted by topic, said once a topic', () => {
    const { fake, socket, firstDrops } = viewer(100);
    socket.send(messageData(1));
    fake.bufferedAmount = 95;
    socket.send(messageData(1));
    socket.send(messageData(1));
    socket.send(messageData(2));
    expect(fake.sent).toHaveLength(1);
    expect(Object.fromEntries(socket.counts.sent)).toEqual({ '/hal/pose': 1 });
    expect(Object.fromEntries(socket.counts.dropped)).toEqual({
      '/hal/pose': 2,
      '/hal/camera': 1,
    });
    expect(firstDrops).toEqual(['/hal/pose', '/hal/camera']);
    fake.bufferedAmount = 0;
    socket.send(messageData(2));
    expect(fake.sent).toHaveLength(2);
  });

  it('never drops what is no topic message: status, advertisements, service answers', () => {
    const { fake, socket } = viewer(10);
    fake.bufferedAmount = 1_000_000;
    socket.send(JSON.stringify({ op: 'status', level: 1, message: 'x' }));
    const serviceResponse = new Uint8Array(20);
    serviceResponse[0] = 3;
    socket.send(serviceResponse);
    expect(fake.sent).toHaveLength(2);
    expect(socket.counts.dropped.size).toBe(0);
  });

  it('hands the protocol server the viewer messages, text as text and binary as an ArrayBuffer', () => {
    const { fake, socket } = viewer();
    const seen: unknown[] = [];
    socket.onmessage = (event) => seen.push(event.data);
    fake.emit('message', Buffer.from('{"op":"unsubscribe","subscriptionIds":[1]}'), false);
    fake.emit('message', Buffer.from([1, 2, 3]), true);
    expect(seen[0]).toBe('{"op":"unsubscribe","subscriptionIds":[1]}');
    expect(seen[1]).toBeInstanceOf(ArrayBuffer);
    expect([...new Uint8Array(seen[1] as ArrayBuffer)]).toEqual([1, 2, 3]);
    // unsubscribed: a message on it no longer names the pose
    fake.bufferedAmount = 1_000_000;
    socket.send(messageData(1));
    expect(Object.fromEntries(socket.counts.dropped)).toEqual({ '?': 1 });
  });
});
