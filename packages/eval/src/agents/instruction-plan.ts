/**
 * What the rule-based baseline reads from an instruction: the steps, in the order the words give
 * them, and the question to answer at the end, if any. Words only: no model, no world.
 */
export type PlanStep =
  | { kind: 'move'; cm: number }
  | { kind: 'turn'; degrees: number }
  | { kind: 'go-to-thing'; target: string; withinCm?: number }
  | { kind: 'go-to-point'; x: number; y: number; withinCm?: number }
  | { kind: 'go-back' }
  | { kind: 'look'; around: boolean };

/** The question an instruction asks, as the baseline answers it. */
export type PlanQuestion =
  | { kind: 'colour'; remembered: boolean; side?: 'left' | 'right' }
  | { kind: 'count'; of: 'box' | 'pillar'; remembered: boolean }
  | { kind: 'open-side' };

export interface InstructionPlan {
  steps: PlanStep[];
  question?: PlanQuestion;
  /** The instruction allows a reset of the e-stop ("you may reset it"). */
  mayResetEstop: boolean;
  /** The instruction says to get as close as a fence allows. */
  closeAsAllowed: boolean;
}

const NUMBER = '(-?\\d+(?:\\.\\d+)?)';
const COLOURS = '(red|orange|yellow|green|blue|purple)';
const KINDS = '(box|boxes|pillar|pillars|cube|cylinder|column|post)';

/** One match of a rule: where it starts, and the step it gives. */
interface Hit {
  at: number;
  end: number;
  step: PlanStep;
}

const cm = (n: string, unit: string) => Number(n) * (unit.startsWith('c') ? 1 : 100);

function withinCm(text: string): number | undefined {
  const m = new RegExp(`within ${NUMBER}\\s*(cm|m)\\b`).exec(text);
  return m === null ? undefined : cm(m[1] ?? '0', m[2] ?? 'cm');
}

/** The rules, each a pattern over the lower-cased instruction and the step a match gives. */
function hits(text: string): Hit[] {
  const found: Hit[] = [];
  const add = (re: RegExp, step: (m: RegExpExecArray) => PlanStep | undefined) => {
    for (const m of text.matchAll(re)) {
      const s = step(m as RegExpExecArray);
      if (s !== undefined)
        found.push({ at: m.index ?? 0, end: (m.index ?? 0) + m[0].length, step: s });
    }
  };
  // points: "x = 1 m, y = -1 m"
  add(
    new RegExp(`x\\s*=\\s*${NUMBER}\\s*m?\\s*,?\\s*(?:and\\s+)?y\\s*=\\s*${NUMBER}\\s*m?`, 'g'),
    (m) => {
      const rest = text.slice((m.index ?? 0) + m[0].length, (m.index ?? 0) + m[0].length + 30);
      const within = withinCm(rest);
      return {
        kind: 'go-to-point',
        x: Number(m[1]),
        y: Number(m[2]),
        ...(within === undefined ? {} : { withinCm: within }),
      };
    },
  );
  // things: "the red box", "the yellow pillar" (a colour, maybe one word, a kind)
  add(new RegExp(`\\b${COLOURS}\\s+(?:[a-z]+\\s+)?${KINDS}\\b`, 'g'), (m) => {
    const rest = text.slice((m.index ?? 0) + m[0].length, (m.index ?? 0) + m[0].length + 60);
    const within = withinCm(rest.split(/[.;]|then/)[0] ?? '');
    return {
      kind: 'go-to-thing',
      target: `${m[1]} ${(m[2] ?? 'box').replace(/e?s$/, '')}`,
      ...(within === undefined ? {} : { withinCm: within }),
    };
  });
  // straight drives: "drive forward 30 cm", "drive 40 cm forward", "back up 40 cm"
  add(
    new RegExp(
      `\\b(drive|move|go|back up|reverse)\\s+(forward|backward|backwards|back|straight)?\\s*${NUMBER}\\s*(cm|m)\\b(\\s+(?:forward|backward|backwards|straight ahead|ahead))?`,
      'g',
    ),
    (m) => {
      const back = /back|reverse/.test(`${m[1] ?? ''} ${m[2] ?? ''} ${m[5] ?? ''}`);
      const size = cm(m[3] ?? '0', m[4] ?? 'cm');
      return { kind: 'move', cm: back ? -size : size };
    },
  );
  // "then another 30 cm": the same way again
  add(new RegExp(`\\banother ${NUMBER}\\s*(cm|m)\\b`, 'g'), (m) => ({
    kind: 'move',
    cm: cm(m[1] ?? '0', m[2] ?? 'cm'),
  }));
  // turns: "turn left 90 degrees", "turn 45 degrees to the right"
  add(
    new RegExp(
      `\\bturn\\s+(left|right)?\\s*${NUMBER}\\s*degrees?(?:\\s+(?:to the\\s+)?(left|right))?`,
      'g',
    ),
    (m) => {
      const side = m[1] ?? m[3] ?? 'left';
      const degrees = Number(m[2]);
      return { kind: 'turn', degrees: side === 'right' ? -degrees : degrees };
    },
  );
  add(
    /\bturn (?:a)?round\b(?:[:,]?\s*(?:to\s+)?face the opposite way)?|\bface the opposite way\b/g,
    () => ({ kind: 'turn', degrees: 180 }),
  );
  // a thing named by its colour alone: "find the purple one"
  add(new RegExp(`\\b(?:find|to|reach) the ${COLOURS} one\\b`, 'g'), (m) => ({
    kind: 'go-to-thing',
    target: m[1] ?? '',
  }));
  add(/\bback to where you start(?:ed)?\b|\breturn to (?:where you started|the start)\b/g, () => ({
    kind: 'go-back',
  }));
  add(/\blook (?:all )?round\b|\blook around\b/g, () => ({ kind: 'look', around: true }));
  add(/\blook at the (?:object|box|thing)\b/g, () => ({ kind: 'look', around: false }));
  return found;
}

/** Drops a hit that lies inside another (a distance inside a point), and repeats of a target. */
function ordered(found: Hit[]): PlanStep[] {
  const sorted = found.sort((a, b) => a.at - b.at || b.end - a.end);
  const steps: PlanStep[] = [];
  let reach = -1;
  for (const hit of sorted) {
    if (hit.at < reach) continue;
    reach = hit.end;
    const last = steps.at(-1);
    if (
      hit.step.kind === 'go-to-thing' &&
      last?.kind === 'go-to-thing' &&
      last.target === hit.step.target
    )
      continue;
    steps.push(hit.step);
  }
  return steps;
}

/** The question sentence's words, and the rest (the commands). */
function splitQuestion(text: string): { commands: string; question: string } {
  const sentences = text.split(/(?<=[.?!])\s+/);
  const isQuestion = (s: string) =>
    s.includes('?') || /\bsay (?:what|how many|which)\b/.test(s) || /\bremember\b/.test(s);
  const question = sentences.filter(isQuestion).join(' ');
  // a sentence that both commands and asks ("Then drive ... and say what colour") keeps its command part
  const commands = sentences
    .map((s) => (isQuestion(s) ? s.replace(/\b(?:and )?say (?:what|how many|which)\b.*$/, '') : s))
    .filter((s) => !s.includes('?'))
    .join(' ');
  return { commands, question };
}

function questionOf(question: string, whole: string): PlanQuestion | undefined {
  const remembered = /\b(?:was|were|had|passed|did you see|remember)\b/.test(question);
  if (/\bwhat colou?r\b/.test(question)) {
    const side = /\bon your right\b|\bright-hand\b|\bto the right\b/.test(whole)
      ? 'right'
      : /\bon your left\b/.test(whole)
        ? 'left'
        : undefined;
    return { kind: 'colour', remembered, ...(side === undefined ? {} : { side }) };
  }
  const count = /\bhow many (boxes|pillars|cylinders)\b/.exec(question);
  if (count !== null)
    return { kind: 'count', of: count[1] === 'boxes' ? 'box' : 'pillar', remembered };
  if (/\bwhich side\b/.test(question)) return { kind: 'open-side' };
  return undefined;
}

/** Reads an instruction into steps and a question. */
export function planInstruction(instruction: string): InstructionPlan {
  const text = instruction.toLowerCase().replace(/[’`]/g, "'").replace(/\s+/g, ' ');
  const { commands, question } = splitQuestion(text);
  const steps = ordered(hits(commands));
  const q = questionOf(question, text);
  return {
    steps,
    ...(q === undefined ? {} : { question: q }),
    mayResetEstop:
      /\bmay reset\b|\bcan reset\b|\breset it\b(?![^.]*\bnot\b)/.test(text) &&
      !/\bdo not reset\b|\bdon't reset\b/.test(text),
    closeAsAllowed: /\bas close as\b/.test(text),
  };
}
