#!/usr/bin/env bash
# deploy/security/access.table and docs/topics.md's writers/readers columns name the same
# identities for every topic; a copy of the catalogue with one writer added must be refused,
# naming the topic and the line.
set -euo pipefail
repo=${1:?usage: access_table_test.sh REPO}
check="$repo/deploy/security/security.sh"
bash "$check" check-table "$repo/docs/topics.md"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The behavior as a second writer of the clock.
sed 's/^\(| `autonomy\/clock` |.*| \)\*\*simulator\*\* · /\1**simulator**, **behavior** · /' "$repo/docs/topics.md" >"$tmp/topics.md"
if cmp -s "$repo/docs/topics.md" "$tmp/topics.md"; then echo "FAIL: the drifted copy is unchanged" >&2; exit 1; fi
if bash "$check" check-table "$tmp/topics.md" 2>"$tmp/err"; then
  echo "FAIL: a catalogue where the behavior writes the clock was accepted" >&2; exit 1
fi
grep -q "topics.md:[0-9]*: autonomy/clock writers: the catalogue says 'behavior,simulator'" "$tmp/err" \
  || { echo "FAIL: the refusal does not name the clock's writers:" >&2; cat "$tmp/err" >&2; exit 1; }
# A topic of the catalogue missing from the table.
grep -v '^| `autonomy/planner/plan`' "$repo/docs/topics.md" >"$tmp/topics2.md"
if bash "$check" check-table "$tmp/topics2.md" 2>"$tmp/err2"; then
  echo "FAIL: a catalogue without autonomy/planner/plan was accepted" >&2; exit 1
fi
grep -q "autonomy/planner/plan is not in" "$tmp/err2" || { cat "$tmp/err2" >&2; exit 1; }
echo "access_table_test: ok"
