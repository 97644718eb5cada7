// When the server asks its client's user before a motion: `--approve motion|over:DISTANCE|none`.

/** Ask before every motion, only before one longer than `overM` metres, or never. */
export type ApprovalPolicy = 'motion' | 'none' | { overM: number };

/** How long a person has to answer, by default, ms: well inside a client's request timeout (60 s in the SDK). */
export const DEFAULT_APPROVAL_TIMEOUT_MS = 30_000;

/** Whether `policy` ever asks. */
export function asks(policy: ApprovalPolicy): boolean {
  return policy !== 'none';
}

/**
 * Whether a motion of `distanceM` metres is asked about: under `motion` every one; under
 * `{ overM }` one longer than that, or one whose length is not known before it runs.
 */
export function needsApproval(policy: ApprovalPolicy, distanceM: number | undefined): boolean {
  if (policy === 'none') return false;
  if (policy === 'motion') return true;
  return distanceM === undefined || distanceM > policy.overM;
}

/** The policy in words, as the command line writes it. */
export function policyText(policy: ApprovalPolicy): string {
  return typeof policy === 'string' ? policy : `over:${policy.overM}m`;
}

/** Parses `motion`, `none` or `over:DISTANCE` (metres, or a unit: `30cm`); TypeError otherwise. */
export function parseApprovalPolicy(
  text: string,
  readDistance: (text: string) => number | undefined,
): ApprovalPolicy {
  if (text === 'motion' || text === 'none') return text;
  if (text.startsWith('over:')) {
    const overM = readDistance(text.slice('over:'.length));
    if (overM !== undefined && Number.isFinite(overM) && overM >= 0) return { overM };
  }
  throw new TypeError(
    `the approval policy must be motion, none or over:DISTANCE (metres, or 30cm), got "${text}"`,
  );
}
