// The Khronos glTF Validator over each file named: a line of counts per file, then each error
// and warning; exits 1 when any file has an error.
const fs = require('fs');
const validator = require('gltf-validator');

(async () => {
  let failed = false;
  for (const file of process.argv.slice(2)) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(bytes, {maxIssues: 20});
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints`);
    for (const m of issues.messages) {
      if (m.severity > 1) continue;
      const kind = m.severity === 0 ? 'error' : 'warning';
      console.log(`  ${kind} ${m.code} at ${m.pointer || '/'}: ${m.message}`);
    }
    failed = failed || issues.numErrors > 0;
  }
  process.exit(failed ? 1 : 0);
})().catch((e) => {
  console.log(`the validator failed: ${e}`);
  process.exit(1);
});
