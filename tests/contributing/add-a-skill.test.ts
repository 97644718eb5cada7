// CONTRIBUTING.md, "Add a skill", done once: a tiny skill written the way packages/skills writes
// its own (a function of the SkillContext that drives through the HAL's public calls and answers
// one sentence, an outcome and its facts), run on SimulationHAL behind the leash as `hal agent`
// runs skills, sharing the context of a real skill set (its built-in `go_back` returns to where
// our skill started). Then what registering it means, checked on the skills that are registered:
// each has its parameters, its tool and its row in docs/agent.md, and a skill set offers only those.
import { readFileSync } from 'node:fs';
import { afterEach, describe, expect, it } from 'vitest';
import { createSkills, SKILL_NAMES, SKILL_PARAMETERS, SKILL_TOOLS, skillPose } from '@hal/skills';
import type { SkillContext, SkillOutcome } from '@hal/skills';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor, halTools, toolBackedHal } from '@hal/tools';
import type { ToolResult } from '@hal/tools';

let sim: SimulationHAL | undefined;
afterEach(async () => {
  await sim?.cleanup();
  sim = undefined;
});

/** The answer shape of every skill (skill-result.ts' `skillResult`). */
function answer(outcome: SkillOutcome, text: string, facts: Record<string, unknown>): ToolResult {
  const isError = outcome === 'refused' || outcome === 'estopped' || outcome === 'failed';
  return {
    isError,
    content: [{ type: 'text', text }],
    structured: { outcome, ...facts, message: text },
  };
}

/** `peek`: drive `cm` forward, turn 90° left to look, and say where it ended. */
async function peekSkill(ctx: SkillContext, cm: number): Promise<ToolResult> {
  await ctx.pose(); // the first pose read is where the run started (go_back returns there)
  const moved = await ctx.hal.locomotion.moveForward(cm);
  if (!moved.success)
    return answer('refused', `Refused, nothing moved: ${moved.error ?? ''}`, { code: moved.code });
  const turned = await ctx.hal.locomotion.rotate('left', 90);
  if (!turned.success) return answer('failed', `The turn failed: ${turned.error ?? ''}`, {});
  const pose = skillPose(await ctx.pose());
  return answer('done', `Moved ${cm} cm and turned left; I face ${pose.yawDeg}°.`, { pose });
}

/** The simulator, leashed (0.5 m per call) as the agent's tools are, and a skill set over it. */
async function skillsOnSimulator() {
  sim = new SimulationHAL();
  await sim.initialize();
  const primitives = createToolExecutor(sim, {
    tools: halTools(sim),
    leash: { maxDistanceM: 0.5 },
  });
  const hal = toolBackedHal(sim, (call) => primitives.execute(call));
  return { sim, skills: createSkills(hal) };
}

describe('a skill of our own (CONTRIBUTING.md: Add a skill)', () => {
  it('runs on SimulationHAL through the leash, and the set it shares a context with takes it home', async () => {
    const { sim: robot, skills } = await skillsOnSimulator();
    const done = await peekSkill(skills.context, 20);
    expect(done.isError).toBe(false);
    expect(done.structured).toMatchObject({ outcome: 'done', pose: { x: 0.2, y: 0, yawDeg: 90 } });
    // the truth, not what the skill says: the simulated robot is 20 cm ahead, facing +y
    expect(robot.robot.x).toBeCloseTo(0.2, 2);

    // the leash refuses a call beyond it, before anything moves, and the skill says so
    const refused = await peekSkill(skills.context, 80);
    expect(refused).toMatchObject({ isError: true, structured: { outcome: 'refused' } });
    expect(robot.robot.x).toBeCloseTo(0.2, 2);

    const back = await skills.execute({ name: 'go_back', arguments: {} });
    expect(back.isError, JSON.stringify(back.structured)).toBe(false);
    expect(Math.hypot(robot.robot.x, robot.robot.y)).toBeLessThan(0.06);
  }, 60_000);

  it('is offered by a skill set only once it is in the catalog', async () => {
    const { skills } = await skillsOnSimulator();
    expect(skills.tools.map((t) => t.name)).toEqual(SKILL_NAMES);
    const unknown = await skills.execute({ name: 'peek', arguments: { cm: 10 } });
    expect(unknown).toMatchObject({ isError: true, code: 'UNKNOWN_TOOL' });
    expect(() => createSkills(sim!, { include: ['peek' as never] })).toThrow(/no skill is called/);
  });

  it('has, for every registered skill, its parameters, its tool and its row in docs/agent.md', () => {
    const agentDoc = readFileSync(new URL('../../docs/agent.md', import.meta.url), 'utf8');
    const skillsTable = agentDoc.slice(agentDoc.indexOf('## Skills'));
    for (const name of SKILL_NAMES) {
      expect(SKILL_TOOLS[name].name, name).toBe(name);
      const schemaKeys = Object.keys(SKILL_TOOLS[name].inputSchema.properties ?? {}).sort();
      expect(schemaKeys, `${name}: the tool's schema and SKILL_PARAMETERS`).toEqual(
        Object.keys(SKILL_PARAMETERS[name].shape).sort(),
      );
      expect(skillsTable, `docs/agent.md's Skills table names ${name}`).toContain(`\`${name}\``);
    }
  });
});
