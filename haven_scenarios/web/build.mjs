// Builds the two pages' bundles into the Python package (haven_scenarios/web/static), so users need
// no Node. Deterministic: the same sources and lock file give the same bytes (a test rebuilds and
// compares). `node build.mjs --out DIR` writes elsewhere.
import * as esbuild from "esbuild";
import path from "node:path";

const out = process.argv.includes("--out") ? process.argv[process.argv.indexOf("--out") + 1] : "../haven_scenarios/web/static";
await esbuild.build({
  entryPoints: { participant: "src/participant.js", console: "src/console.js" },
  bundle: true,
  minify: true,
  format: "esm",
  target: "es2022",
  legalComments: "linked",
  outdir: path.resolve(out),
  logLevel: "warning",
});
