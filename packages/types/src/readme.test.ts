import { expect, it } from 'vitest';
import { HalBoundary, isHalError, V1_ROBOT } from './index.js';

it('README: the boundary refuses a move longer than one command allows, naming the limit', async () => {
  const boundary = new HalBoundary({
    mode: 'simulation',
    config: () => V1_ROBOT,
    isEmergencyStopped: () => false,
    isReady: () => true,
  });
  const result = await boundary.call('moveForward', { distanceCm: 500 }, async () => undefined);
  expect(result).toMatchObject({ success: false, code: 'RANGE_EXCEEDED' });
  expect(result.error).toMatch(
    /^moveForward: "distanceCm" must be at most 188\.4, got 500 \(Distance, cm/,
  );
});

it('README: a read call rejects an unknown scan mode with INVALID_PARAMETER listing the modes', async () => {
  const boundary = new HalBoundary({
    mode: 'simulation',
    config: () => V1_ROBOT,
    isEmergencyStopped: () => false,
    isReady: () => true,
  });
  const scanAround = () => ({ objects: [], clearAhead: true });
  const error: unknown = await boundary
    .read('scan', { mode: 'bogus' }, async () => scanAround())
    .catch((e: unknown) => e);
  expect(isHalError(error) && error.code).toBe('INVALID_PARAMETER');
  expect((error as Error).message).toMatch(
    /^scan: "mode" must be one of "full", "targeted", "quick", got "bogus" \(/,
  );
});
