#!/usr/bin/env bash
# Validates glTF files with the Khronos glTF validator (npm package gltf-validator), installed once
# into TOOLDIR (outside the repository, e.g. the build folder). Prints each report's issues and
# exits 1 when any file has errors, 0 when none does, 77 (ctest: skipped) when node/npm are missing
# or the npm registry cannot be reached.
# Usage: scripts/gltf-validate.sh TOOLDIR FILE.glb [FILE.gltf ...]
set -euo pipefail
tooldir=${1:?usage: gltf-validate.sh TOOLDIR FILE...}
shift
[ $# -gt 0 ] || { echo "usage: gltf-validate.sh TOOLDIR FILE..." >&2; exit 2; }
version=2.0.0-dev.3.10

"$(dirname "$0")/npm-tool.sh" "$tooldir" "gltf-validator@$version"

cat >"$tooldir/validate.js" <<'JS'
// Runs the Khronos validator on each file; exit code 1 when any report has errors.
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');
(async () => {
  let errors = 0;
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      maxIssues: 200,
      externalResourceFunction: (uri) =>
        new Promise((resolve, reject) => fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)),
                                                     (err, data) => err ? reject(err.toString()) : resolve(new Uint8Array(data)))),
    });
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints` +
                ` (validator ${report.validatorVersion})`);
    for (const m of i.messages) console.log(`  [${['error', 'warning', 'info', 'hint'][m.severity]}] ${m.code} ${m.pointer || ''}: ${m.message}`);
    errors += i.numErrors;
  }
  process.exit(errors > 0 ? 1 : 0);
})().catch((e) => { console.error(e); process.exit(1); });
JS
node "$tooldir/validate.js" "$@"
