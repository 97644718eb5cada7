// @foxglove/ws-protocol as Node loads it. The package's `main` is CommonJS whose named exports
// Node's ES module loader cannot see (`import { FoxgloveServer }` fails outside a bundler), so
// it is required; its types are the package's own.
import { createRequire } from 'node:module';
import type * as WsProtocolModule from '@foxglove/ws-protocol';

type WsProtocol = typeof WsProtocolModule;

const wsProtocol = createRequire(import.meta.url)('@foxglove/ws-protocol') as WsProtocol;

export const { FoxgloveServer, ServerCapability, StatusLevel } = wsProtocol;
