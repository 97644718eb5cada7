/** A decoded request or reply object. */
export type Json = Record<string, unknown>;

/** A request the robot refuses: the `error` of its reply (protocol 1.1, section 6). */
export class Refusal extends Error {
  constructor(
    readonly code: string,
    message: string,
    readonly details: Json = {},
  ) {
    super(message);
  }
}

/** A request's number field; INVALID_PARAMETER unless it is a finite number. */
export function numberField(request: Json, field: string): number {
  const value = request[field];
  if (typeof value !== 'number')
    throw new Refusal('INVALID_PARAMETER', `"${field}" must be a number`, { field });
  // JSON.parse reads 1e400 as Infinity, as the firmware's reader does; the protocol's numbers are finite
  if (!Number.isFinite(value))
    throw new Refusal('INVALID_PARAMETER', `"${field}" must be a finite number`, { field });
  return value;
}

/** A request's int field; INVALID_PARAMETER unless it is a number with no fractional part. */
export function integerField(request: Json, field: string): number {
  const value = request[field];
  if (typeof value !== 'number' || !Number.isInteger(value))
    throw new Refusal('INVALID_PARAMETER', `"${field}" must be an integer`, { field });
  return value;
}

/** Whether a request field is absent (`null` counts as absent). */
export function isAbsent(request: Json, field: string): boolean {
  return request[field] === undefined || request[field] === null;
}
