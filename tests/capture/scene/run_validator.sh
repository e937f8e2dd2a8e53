#!/bin/sh
# SPDX-License-Identifier: MIT
# run_validator.sh NODE MODULES SCRIPT FILE...: validate_gltf.mjs on the files; exits 77
# (ctest: skipped) without Node.js or without the gltf-validator package in MODULES
# (`make test` installs it into build/node/node_modules).
node=$1 modules=$2 script=$3
shift 3
if [ -z "$node" ] || [ ! -x "$node" ] || [ ! -d "$modules/gltf-validator" ]; then
  echo "gltf-validator not available (node: '$node', modules: $modules): skipped"
  exit 77
fi
exec "$node" "$script" "$modules" "$@"
