#!/usr/bin/env bash
# The studio's HTTP under slow, idle and malformed clients (studio_clients.py, with real processes).
# usage: studio.sh SELFSIM SOURCE_DIR
exec /usr/bin/python3 "$(dirname "$0")/studio_clients.py" "$1"
