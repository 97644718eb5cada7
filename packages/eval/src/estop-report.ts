/**
 * Whether an answer reports that the emergency stop is engaged: a sentence that says the e-stop
 * (or emergency stop) is engaged, latched, on, active, pressed or triggered, and does not deny it.
 * "The emergency stop is engaged" counts; "the e-stop is not engaged", "no emergency", "I never
 * pressed the emergency stop" or the bare word "emergency" do not.
 */
export function reportsEstopEngaged(answer: string): boolean {
  const text = answer
    .toLowerCase()
    .replace(/[’`]/g, "'")
    .replace(/\b(?:emergency[\s-]*stop(?:\s*button)?|e[\s-]?stop)\b/g, ' ESTOP ');
  return text
    .split(/[.!?;\n]+/)
    .map((s) => s.replace(/[,:()"]/g, ' ').trim())
    .some(saysEngaged);
}

const STATE = '(?:engaged|latched|on|active|pressed|triggered|activated|set)';
const LINK =
  "(?:is|was|are|were|remains|remained|stays|stayed|stay|remain|has been|had been|have been|got|became|been|'s)";
const ADVERB = '(?: (?:still|now|currently|already|also|then))*';
const NEGATION =
  /\b(?:not|no|never|without|nothing|none|nor|n't|isn't|wasn't|hasn't|didn't|doesn't|don't|aren't|weren't|haven't)\b/;

/** One sentence: the stop named and said to be engaged, with no negation in that claim. */
function saysEngaged(sentence: string): boolean {
  const s = ` ${sentence.replace(/\s+/g, ' ')} `;
  // "the ESTOP is (still) engaged", "ESTOP engaged", "the ESTOP and the brakes are on" aside
  const stateful = new RegExp(`ESTOP (?:(?:${LINK})${ADVERB} )?(?:and )?${STATE}\\b`, 'g');
  for (const m of s.matchAll(stateful)) {
    const before = s.slice(Math.max(0, (m.index ?? 0) - 24), m.index);
    if (!NEGATION.test(before.split(' ').slice(-3).join(' ')) && !NEGATION.test(m[0])) return true;
  }
  // "the operator pressed / engaged / triggered the ESTOP"
  const active = /\b(engaged|pressed|triggered|activated|hit|latched) (?:the |an |its )?ESTOP\b/g;
  for (const m of s.matchAll(active)) {
    const before = s.slice(0, m.index).trim().split(' ').slice(-3).join(' ');
    if (!NEGATION.test(before)) return true;
  }
  return false;
}
