// @foxglove/ws-protocol as Node loads it. The package's `main` is CommonJS whose named exports
// Node's ES module loader cannot see (`import { FoxgloveServer }` fails outside a bundler), so
// it is required; its types are the package's own.
import { createRequire } from 'node:module';
import type * as WsProtocolModule from '@foxglove/ws-protocol';

type WsProtocol = typeof WsProtocolModule;

const wsProtocol = createRequire(import.meta.url)('@foxglove/ws-protocol') as WsProtocol;

export const { FoxgloveServer, ServerCapability, StatusLevel } = wsProtocol;

/** A message's bytes (the protocol hands an ArrayBufferView) as what every TextDecoder takes. */
export function bytesOf(view: ArrayBufferView): Uint8Array {
  return new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
}
