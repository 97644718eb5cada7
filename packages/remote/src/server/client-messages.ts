import { toHalError } from '@hal/types';
import type { RawData } from 'ws';
import { MESSAGE_SCHEMAS, decodeArgs, decodeMessage, readRequestId } from '../protocol.js';
import type { ClientSession } from './client-session.js';
import type { ServerState } from './server-state.js';
import { errorOf } from './session-output.js';

/**
 * Handles one message from a client: refuses an oversized, binary or unreadable one with an
 * error reply, and otherwise runs its call, notes its subscription or hands it control.
 */
export function onClientMessage(
  state: ServerState,
  session: ClientSession,
  data: RawData,
  isBinary: boolean,
): void {
  const { controllers, out, settings } = state;
  controllers.heard(session.id);
  const size = messageSize(data);
  const text = isBinary ? '' : Buffer.isBuffer(data) ? data.toString('utf8') : String(data);
  if (size > settings.maxMessageBytes) {
    out.reply(
      session,
      readRequestId(text),
      null,
      errorOf(
        'MALFORMED',
        `message of ${size} bytes is over the ${settings.maxMessageBytes}-byte limit`,
      ),
    );
    return;
  }
  if (isBinary) {
    out.reply(session, null, null, errorOf('MALFORMED', 'binary messages are not accepted'));
    return;
  }
  let message: ReturnType<typeof decodeMessage>;
  try {
    message = decodeMessage(text);
  } catch (e) {
    out.reply(session, readRequestId(text), null, toHalError(e));
    return;
  }
  switch (message.schema) {
    case MESSAGE_SCHEMAS.call: {
      const { id, call, args } = message.envelope.payload;
      runCall(state, session, id, call, args);
      return;
    }
    case MESSAGE_SCHEMAS.heartbeat:
      return;
    case MESSAGE_SCHEMAS.subscribe:
      session.subscribed = message.envelope.payload.state;
      return;
    case MESSAGE_SCHEMAS.takeControl:
      takeControl(state, session, message.envelope.payload.id ?? null);
      return;
    default:
      out.reply(
        session,
        null,
        null,
        errorOf('MALFORMED', `"${message.schema}" is not a message a client sends`),
      );
  }
}

/** The size in bytes of a message as ws hands it over. */
function messageSize(data: RawData): number {
  return Array.isArray(data)
    ? data.reduce((n, b) => n + b.length, 0)
    : data instanceof ArrayBuffer
      ? data.byteLength
      : data.length;
}

/**
 * Runs a client's call the moment it arrives (a watcher is refused the controller's calls), and
 * replies with its outcome; a motion counts as running for the state stream until it ends.
 */
function runCall(
  state: ServerState,
  session: ClientSession,
  id: string,
  call: string,
  rawArgs: unknown[],
): void {
  const { served, out } = state;
  const spec = served.find(call);
  if (spec === undefined) {
    out.reply(session, id, null, errorOf('UNKNOWN_COMMAND', `unknown call "${call}"`, { call }));
    return;
  }
  const hint = 'send hal.remote.take_control first';
  const refusal = served.refusal(spec, session.role === 'controller', hint);
  if (refusal !== undefined) {
    out.reply(session, id, null, refusal);
    return;
  }
  const motion = spec.kind === 'motion';
  if (motion) session.running += 1;
  served
    .run(spec, decodeArgs(rawArgs))
    .then(
      (value) => out.reply(session, id, value),
      (e: unknown) => out.reply(session, id, null, toHalError(e)),
    )
    .finally(() => {
      if (motion) session.running -= 1;
    });
}

/** Makes `session` the controller; the one it replaces becomes a watcher and is told by whom. */
function takeControl(state: ServerState, session: ClientSession, id: string | null): void {
  const previous = state.controller;
  if (previous !== session) {
    state.controller = session;
    if (previous !== undefined) {
      state.out.setRole(previous, 'watcher', `control taken by client ${session.id}`);
    }
    state.log('info', `client ${session.id} took control`, { previous: previous?.id });
  }
  state.out.setRole(session, 'controller', 'control taken');
  state.out.reply(session, id, { role: 'controller' });
}
