import { describe, expect, it } from 'vitest';
import { natsPort } from './announce-node.js';

describe('natsPort', () => {
  it("reads the port of a NATS server URL, or NATS's 4222 when it names none", () => {
    expect(natsPort('nats://127.0.0.1:4333')).toBe(4333);
    expect(natsPort('127.0.0.1:5222')).toBe(5222);
    expect(natsPort('tls://nats.example.org:4443/')).toBe(4443);
    expect(natsPort('nats://robots.local')).toBe(4222);
    expect(natsPort('nats://[::1]:4224')).toBe(4224);
  });
});
