#!/usr/bin/env node
// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Runs the Khronos glTF validator (the gltf-validator npm package that
// scripts/setup.sh installs into build-tools/node_modules) on each file
// given. Prints every message; exits 1 when any file has an error, 2 when
// the validator is not installed or a file cannot be read.
'use strict';
const fs = require('fs');
const path = require('path');

let validator;
try {
  validator = require(path.join(__dirname, '..', 'build-tools', 'node_modules', 'gltf-validator'));
} catch (e) {
  console.error('gltf-validate: the gltf-validator package is missing; run scripts/setup.sh');
  process.exit(2);
}

async function main() {
  let failed = false;
  for (const file of process.argv.slice(2)) {
    let bytes;
    try {
      bytes = new Uint8Array(fs.readFileSync(file));
    } catch (e) {
      console.error(`gltf-validate: cannot read ${file}: ${e.message}`);
      process.exit(2);
    }
    const report = await validator.validateBytes(bytes, {
      uri: file,
      maxIssues: 0,
      externalResourceFunction: (uri) =>
        Promise.reject(new Error(`external resource ${uri}: Q3 embeds everything`)),
    });
    const issues = report.issues;
    for (const m of issues.messages)
      console.log(`${file}: severity ${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings`);
    if (issues.numErrors > 0)
      failed = true;
  }
  process.exit(failed ? 1 : 0);
}

main().catch((e) => {
  console.error(`gltf-validate: ${e.message}`);
  process.exit(2);
});
