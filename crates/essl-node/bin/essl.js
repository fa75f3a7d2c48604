#!/usr/bin/env node
// `npx essl …`: the essl command (lint, explain, rules, config, translate, server), the same
// code as the `essl` binary, run in this process.
import {runCli} from '../index.js';

process.exitCode = runCli(process.argv.slice(2));
