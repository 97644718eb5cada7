/**
 * Codes that mean a call was refused before it ran, so nothing moved: the executor's own (the
 * leash, approval, a bad or unknown call, a budget) and the HAL's validation (a parameter out of
 * the robot's limits, or invalid). The e-stop's refusal is `EMERGENCY_STOPPED`, apart: a caller
 * may tell it from the others.
 */
export const REFUSAL_CODES: ReadonlySet<string> = new Set([
  'LEASH_DISTANCE',
  'LEASH_SPEED',
  'LEASH_GEOFENCE',
  'LEASH_RATE',
  'DENIED',
  'BAD_ARGUMENTS',
  'UNKNOWN_TOOL',
  'INVALID_PARAMETER',
  'RANGE_EXCEEDED',
  'BUDGET_EXCEEDED',
]);
