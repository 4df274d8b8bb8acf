// Validates a .glb with the Khronos glTF validator and prints "errors E warnings W", then each
// issue: used by tests/engine/io/gltf_export_test.cpp when node and gltf-validator are installed.
const fs = require('fs');
const validator = require('gltf-validator');
const bytes = new Uint8Array(fs.readFileSync(process.argv[2]));
validator.validateBytes(bytes, {maxIssues: 50}).then((report) => {
  const issues = report.issues;
  console.log(`errors ${issues.numErrors} warnings ${issues.numWarnings}`);
  for (const m of issues.messages) console.log(`${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
}, (error) => {
  console.log(`validator failed: ${error}`);
  process.exit(1);
});
