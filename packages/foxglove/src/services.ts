// The services a viewer calls (Foxglove's Service Call panel, JSON): stop, emergency_stop and
// reset_emergency_stop. Stop and the e-stop go straight to the robot, never refused or held;
// the reset goes through the leash (its approval) like any other call. Each answers the HAL's
// result as JSON: {success, error?, code?, emergency_stopped}.
import { StatusLevel, bytesOf } from './ws-protocol.js';
import type { FoxgloveServer, IWebSocket, ServiceCallRequest } from '@foxglove/ws-protocol';
import type { HALToolResult, HardwareAbstractionLayer, LogLevel } from '@hal/types';
import type { ControlNames } from './topics.js';

const encoder = new TextEncoder();
const decoder = new TextDecoder();

const jsonSchema = (properties: Record<string, unknown>) =>
  JSON.stringify({ type: 'object', properties });

const RESPONSE = jsonSchema({
  success: { type: 'boolean' },
  error: { type: 'string' },
  code: { type: 'string' },
  emergency_stopped: { type: 'boolean' },
});

type Run = (request: Record<string, unknown>) => Promise<HALToolResult>;

/** Advertises the services on `server`; `call` answers one request. */
export function controlServices(
  server: FoxgloveServer,
  hal: HardwareAbstractionLayer,
  leashed: HardwareAbstractionLayer,
  names: ControlNames,
  log: (level: LogLevel, message: string) => void,
): { call(request: ServiceCallRequest, connection: IWebSocket): void } {
  const runs = new Map<number, { name: string; run: Run }>();
  const add = (name: string, request: string, run: Run) => {
    const id = server.addService({
      name,
      type: `hal/${name.split('/').pop() ?? name}`,
      request: {
        encoding: 'json',
        schemaName: `${name}_Request`,
        schemaEncoding: 'jsonschema',
        schema: request,
      },
      response: {
        encoding: 'json',
        schemaName: `${name}_Response`,
        schemaEncoding: 'jsonschema',
        schema: RESPONSE,
      },
    });
    runs.set(id, { name, run });
  };
  add(names.stop, jsonSchema({}), () => hal.locomotion.stop());
  add(
    names.emergencyStop,
    jsonSchema({ reason: { type: 'string', description: 'why, kept with the e-stop' } }),
    (request) =>
      hal.safety.emergencyStop(
        typeof request['reason'] === 'string' ? request['reason'] : 'e-stop from a viewer',
      ),
  );
  add(names.resetEmergencyStop, jsonSchema({}), () => leashed.safety.resetEmergencyStop());

  return {
    call(request, connection) {
      const service = runs.get(request.serviceId);
      if (service === undefined) return;
      let body: Record<string, unknown> = {};
      try {
        const text = decoder.decode(bytesOf(request.data));
        const parsed: unknown = text.trim() === '' ? {} : JSON.parse(text);
        if (typeof parsed === 'object' && parsed !== null) body = parsed as Record<string, unknown>;
      } catch {
        // an unreadable request still stops the robot; its arguments are just not read
        body = {};
      }
      log('info', `service ${service.name} called by a viewer`);
      const answer = (result: Record<string, unknown>) => {
        server.sendServiceCallResponse(
          {
            serviceId: request.serviceId,
            callId: request.callId,
            encoding: 'json',
            data: encoder.encode(JSON.stringify(result)),
          },
          connection,
        );
      };
      service.run(body).then(
        (result) => {
          const latched = safeLatch(hal);
          answer({
            success: result.success,
            ...(result.error === undefined ? {} : { error: result.error }),
            ...(result.code === undefined ? {} : { code: result.code }),
            emergency_stopped: latched,
          });
          if (!result.success) {
            server.sendStatus(
              {
                level: StatusLevel.WARNING,
                message: `${service.name}: ${result.error ?? 'failed'}`,
              },
              connection,
            );
          }
        },
        (error: unknown) => {
          server.sendServiceCallFailure(
            {
              op: 'serviceCallFailure',
              serviceId: request.serviceId,
              callId: request.callId,
              message: String(error),
            },
            connection,
          );
        },
      );
    },
  };
}

function safeLatch(hal: HardwareAbstractionLayer): boolean {
  try {
    return hal.safety.isEmergencyStopped();
  } catch {
    return false;
  }
}
