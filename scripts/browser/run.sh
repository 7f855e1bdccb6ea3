#!/usr/bin/env bash
# The browser test of replay.html: builds the debug `vorrt`, installs
# playwright-core from package-lock.json if needed (npm ci; it downloads no
# browser) and runs replay_test.mjs in Debian's Chromium (/usr/bin/chromium,
# `apt-get install chromium`). Screenshots go to target/browser-test/screenshots/.
set -euo pipefail
cd "$(dirname "$0")"
if [ ! -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
    echo "the browser test needs Chromium at /usr/bin/chromium (apt-get install chromium) or CHROMIUM=path" >&2
    exit 1
fi
if [ ! -d node_modules/playwright-core ]; then
    npm ci --no-audit --no-fund
fi
(cd ../.. && cargo build --bin vorrt --quiet)
node replay_test.mjs
