#!/usr/bin/env bash
# Previews in the studio: a child under the run's limits, answered around, cleaned up (studio_previews.py).
# usage: studio_previews.sh SELFSIM SOURCE_DIR
exec /usr/bin/python3 "$(dirname "$0")/studio_previews.py" "$1"
