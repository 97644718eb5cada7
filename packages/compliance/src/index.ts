export { runCompliance } from './runner.js';
export { DEFAULT_SEEN_WINDOW_MS, devicesSeenOnNats } from './discover.js';
export type { SeenDevice } from './discover.js';
export { formatReport } from './format-report.js';
export { SPEC_CAPABILITIES, specCapability } from './spec.js';
export type { LatencyClass, SpecCapability } from './spec.js';
export type { ComplianceOptions, ProgressEvent } from './options.js';
export { CHECK_GROUPS } from './report.js';
export type { CheckGroup, CheckResult, CheckStatus, ComplianceReport, Measured } from './report.js';
