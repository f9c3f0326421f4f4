#!/usr/bin/env bash
# Path-traces the reference comparisons' references afresh and stores them in
# tests/golden/reference/ (tests/gpu/stored_reference.hpp), then runs the comparisons on
# them. Deliberate: after a change to the path tracer or to a compared scene; read the
# figures it prints against the bounds and docs/REFERENCE.md before committing. It takes
# the path tracer's full time (about 12 CPU-minutes for all of them).
#
#   scripts/bless-references.sh                        # every case
#   scripts/bless-references.sh lager_pint stout_head  # only these
exec "$(dirname "$0")/bless-goldens.sh" --references "$@"
