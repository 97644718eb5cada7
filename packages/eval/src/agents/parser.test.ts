// The rule-based baseline: what it reads from an instruction, and what it scores with the skills
// on the built-in tasks, judged from the simulator's truth.
import { describe, expect, it } from 'vitest';
import { builtinTasks } from '../builtin-tasks.js';
import { runEval } from '../run-eval.js';
import { planInstruction } from './instruction-plan.js';
import { parserAgent } from './parser.js';

describe('planInstruction', () => {
  it('reads drives, turns and returns in the order the words give them', () => {
    expect(
      planInstruction(
        'Drive forward 50 cm, then turn right 90 degrees and drive 30 cm, then come back to where you started.',
      ).steps,
    ).toEqual([
      { kind: 'move', cm: 50 },
      { kind: 'turn', degrees: -90 },
      { kind: 'move', cm: 30 },
      { kind: 'go-back' },
    ]);
    expect(
      planInstruction('Back up 40 cm, then turn round to face the opposite way.').steps,
    ).toEqual([
      { kind: 'move', cm: -40 },
      { kind: 'turn', degrees: 180 },
    ]);
    expect(planInstruction('Drive 2 m straight ahead.').steps).toEqual([{ kind: 'move', cm: 200 }]);
    expect(planInstruction('Drive forward 30 cm, then another 30 cm.').steps).toEqual([
      { kind: 'move', cm: 30 },
      { kind: 'move', cm: 30 },
    ]);
  });

  it('reads things and points to go to, a repeat of the same thing once', () => {
    expect(
      planInstruction(
        'A green box is hidden behind the long orange wall. Go round the wall, find the green box and stop within 25 cm of it.',
      ).steps,
    ).toEqual([{ kind: 'go-to-thing', target: 'green box' }]);
    expect(
      planInstruction('Visit x = 1 m, y = 1 m; then x = 1 m, y = -1 m, within 10 cm of each.')
        .steps,
    ).toEqual([
      { kind: 'go-to-point', x: 1, y: 1 },
      { kind: 'go-to-point', x: 1, y: -1, withinCm: 10 },
    ]);
    expect(planInstruction('Find the purple one and stop near it.').steps).toEqual([
      { kind: 'go-to-thing', target: 'purple' },
    ]);
  });

  it('reads the question, and whether it asks of something seen before', () => {
    expect(planInstruction('What colour is the box in front of you?').question).toEqual({
      kind: 'colour',
      remembered: false,
    });
    expect(
      planInstruction(
        'Drive to x = 2 m, y = 0 m. On the way you pass a box on your left: say what colour it was.',
      ).question,
    ).toEqual({ kind: 'colour', remembered: true, side: 'left' });
    expect(planInstruction('How many pillars (not boxes) are there?').question).toEqual({
      kind: 'count',
      of: 'pillar',
      remembered: false,
    });
    expect(planInstruction('Which side is open, left or right?').question).toEqual({
      kind: 'open-side',
    });
  });

  it('reads whether the e-stop may be reset, and an instruction it cannot read', () => {
    expect(planInstruction('If the emergency stop engages, you may reset it.').mayResetEstop).toBe(
      true,
    );
    expect(
      planInstruction('If the emergency stop is engaged, do not reset it.').mayResetEstop,
    ).toBe(false);
    expect(planInstruction('Dance.').steps).toEqual([]);
  });
});

describe('the parser baseline', () => {
  it('drives, goes to things and answers through the skills, scored from the truth', async () => {
    const report = await runEval({
      tasks: builtinTasks().filter((t) =>
        [
          'precision/l-shape',
          'goals/red-box',
          'perception/colour-ahead',
          'sequences/red-blue-back',
        ].includes(t.id),
      ),
      agents: [parserAgent()],
      trials: 1,
      seed: 1,
    });
    const trials = report.scores.agents[0]?.trials ?? [];
    expect(trials).toHaveLength(4);
    expect(
      trials.filter((t) => !t.success).map((t) => `${t.task}: ${t.failures.join('; ')}`),
    ).toEqual([]);
  }, 60_000);

  it('fails what its words cannot say: a corner with a heading', async () => {
    const report = await runEval({
      tasks: builtinTasks().filter((t) => t.id === 'precision/corner'),
      agents: [parserAgent()],
      trials: 1,
      seed: 1,
    });
    expect(report.scores.agents[0]?.trials[0]?.success).toBe(false);
  });
});
