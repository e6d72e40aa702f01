#!/usr/bin/env bash
# placeholder
"$1"/run_tests
