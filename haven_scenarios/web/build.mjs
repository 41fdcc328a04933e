// Builds the pages' bundles into the Python package (haven_scenarios/web/static), so users need
// no Node. Deterministic: the same sources and lock file give the same bytes (a test rebuilds and
// compares). `node build.mjs --out DIR` writes elsewhere; `--xr-emulator FILE` builds the tests'
// emulated headset (test/xr_emulator.js) instead.
import * as esbuild from "esbuild";
import path from "node:path";

const emulator = process.argv.includes("--xr-emulator") ? process.argv[process.argv.indexOf("--xr-emulator") + 1] : null;
if (emulator) {
  await esbuild.build({ entryPoints: ["test/xr_emulator.js"], bundle: true, format: "iife", outfile: path.resolve(emulator), logLevel: "warning" });
  process.exit(0);
}
const out = process.argv.includes("--out") ? process.argv[process.argv.indexOf("--out") + 1] : "../haven_scenarios/web/static";
await esbuild.build({
  entryPoints: { participant: "src/participant.js", console: "src/console.js", instruments: "src/instruments.js", editor: "src/editor.js" },
  bundle: true,
  minify: true,
  format: "esm",
  target: "es2022",
  legalComments: "linked",
  outdir: path.resolve(out),
  logLevel: "warning",
});
