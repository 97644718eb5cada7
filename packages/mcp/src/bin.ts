#!/usr/bin/env node
import { CommanderError } from 'commander';
import { runCli } from './cli.js';

runCli(process.argv.slice(2)).catch((error: unknown) => {
  if (error instanceof CommanderError) process.exit(error.exitCode);
  process.stderr.write(`hal-mcp: ${error instanceof Error ? error.message : String(error)}\n`);
  process.exit(1);
});
