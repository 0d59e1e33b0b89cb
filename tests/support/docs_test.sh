#!/usr/bin/env bash
# The docs stay true: every repository path a Markdown file or a code comment names exists, every
# flag a Markdown file shows after `rigidreel SUBCOMMAND` is in that subcommand's --help, and every
# whole scene it shows (a ```yaml block with `bodies:`) passes `rigidreel check`.
# usage: docs_test.sh RIGIDREEL SOURCE_DIR
set -u
bin=$1 src=$2
cd "$src" || exit 2
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

mapfile -t docs < <(git ls-files '*.md' 2>/dev/null || find . -name '*.md' -not -path './build*' -not -path './out/*')
[ ${#docs[@]} -gt 0 ] || { echo "no Markdown files found in $src"; exit 1; }

# 1. paths: `sim/...`, `render/...`, `scenes/...`, `tests/...`, `.ci/...` in backticks or link
# targets, from the repository's root or from the Markdown file's own folder
roots='(sim|render|scenes|tests|\.ci)/'
for doc in "${docs[@]}"; do
  dir=$(dirname "$doc")
  while IFS=: read -r line token; do
    token=${token%%[),.:;]}
    case $token in *'<'*|*'>'*|*'{'*|*'$'*|*'N'.yaml) continue ;; esac
    found=0
    for base in . "$dir"; do
      if [[ $token == *'*'* ]]; then
        compgen -G "$base/$token" >/dev/null && found=1
      elif [ -e "$base/$token" ]; then found=1; fi
    done
    [ $found = 1 ] || fail "$doc:$line names \`$token\`, which does not exist"
  done < <(grep -noE "(\`|\]\()$roots[A-Za-z0-9_./*-]*" "$doc" | sed -E 's/:(`|\]\()/:/')
done

# 1c. the same paths named in the code's comments (C++, shell, CMake, the Makefile, CI): from the
# repository's root; a module named without its extension (`sim/yaml/first_document`) is its .h
while IFS=: read -r file line token; do
  token=${token%%[),.:;]}
  token=${token%.}
  case $token in *'<'*|*'>'*|*'{'*|*'$'*|*'*'*) continue ;; esac
  [ -e "$token" ] || [ -e "$token.h" ] || fail "$file:$line names \`$token\` in a comment, which does not exist"
done < <(git ls-files '*.cpp' '*.h' '*.sh' 'CMakeLists.txt' '*/CMakeLists.txt' Makefile .ci/run 2>/dev/null |
  xargs grep -HnoE "(//|# ).*" 2>/dev/null |
  sed -nE "s/^([^:]*):([0-9]+):.*[^A-Za-z0-9_\/.]((sim|render|scenes|tests|\.ci)\/[A-Za-z0-9_.\/-]*).*/\1:\2:\3/p")

# 1b. links as a browser follows them: a relative target from the Markdown file's own folder, and
# a `#fragment` naming a heading of its target (GitHub's anchors: lower case, punctuation dropped,
# spaces to hyphens)
python3 - "${docs[@]}" <<'PY' || failures=$((failures + 1))
import os, re, sys
def anchors(path):
    found, seen = set(), {}
    for line in open(path, encoding="utf-8"):
        m = re.match(r"#{1,6} (.*)", line)
        if not m or line.startswith("#!"):
            continue
        slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        found.add(slug if n == 0 else "%s-%d" % (slug, n))
    return found
bad = 0
for doc in sys.argv[1:]:
    text = open(doc, encoding="utf-8").read()
    text = re.sub(r"```.*?```", lambda block: "\n" * block.group(0).count("\n"), text, flags=re.S)
    for m in re.finditer(r"\]\(([^)\s]+)\)", text):
        target = m.group(1)
        if re.match(r"[a-z]+:", target):
            continue
        path, _, fragment = target.partition("#")
        file = os.path.normpath(os.path.join(os.path.dirname(doc), path)) if path else doc
        line = text.count("\n", 0, m.start()) + 1
        if not os.path.exists(file):
            print("FAIL: %s:%d links to %s, which does not exist from %s" % (doc, line, target, os.path.dirname(doc) or "."))
            bad += 1
        elif fragment and file.endswith(".md") and fragment not in anchors(file):
            print("FAIL: %s:%d links to %s, a heading %s lacks" % (doc, line, target, file))
            bad += 1
sys.exit(1 if bad else 0)
PY

# 2. flags shown after `rigidreel SUBCOMMAND` exist in its --help
subcommands=$("$bin" --help 2>&1 | awk '/^Subcommands:/{on=1; next} on && /^  [a-z]/{print $1} on && /^$/{on=0}')
[ -n "$subcommands" ] || { echo "could not read the subcommands from '$bin --help'"; exit 1; }
for sub in $subcommands; do "$bin" "$sub" --help >"$work/help-$sub" 2>&1; done
for doc in "${docs[@]}"; do
  while IFS=: read -r line text; do
    # each `rigidreel SUB [SUBSUB] ...` on the line, up to the closing backtick or quote
    while read -r shown; do
      read -r _ sub next _ <<<"$shown"
      help="$work/help-$sub"
      [ -f "$help" ] || continue
      if [[ $next =~ ^[a-z]+$ ]] && "$bin" "$sub" "$next" --help >"$work/help-$sub-$next" 2>&1; then
        help="$work/help-$sub-$next" sub="$sub $next"
      fi
      for flag in $(grep -oE -- "(^| |\[)--[a-z][a-z0-9-]*" <<<"$shown" | grep -oE -- '--[a-z0-9-]+' | sort -u); do
        grep -qE -- "(^|[ ,])$flag([ =,]|$)" "$help" \
          || fail "$doc:$line shows 'rigidreel $sub $flag', which 'rigidreel $sub --help' does not list"
      done
    done < <(grep -oE "rigidreel [a-z0-9]+[^\`\"']*" <<<"$text")
  done < <(grep -nE "rigidreel [a-z0-9]+ .*--[a-z]" "$doc")
done

# 3. whole scenes shown in ```yaml blocks pass check
for doc in "${docs[@]}"; do
  awk -v out="$work/scene" -v doc="$doc" '
    /^[ \t]*```yaml/ { on = 1; n++; start = NR; indent = index($0, "`") - 1
                       file = out "-" n ".yaml"; printf "" > file; next }
    on && /^[ \t]*```/ { on = 0; close(file); print file ":" start; next }
    on { print substr($0, indent + 1) >> file }' "$doc" >"$work/blocks"
  while IFS=: read -r file start; do
    grep -qE '^ *bodies:' "$file" || continue
    "$bin" check -q "$file" >"$work/check.out" 2>&1 \
      || fail "$doc:$start shows a scene that 'rigidreel check' refuses: $(head -3 "$work/check.out")"
  done <"$work/blocks"
  rm -f "$work"/scene-*.yaml
done

echo "$failures failures in ${#docs[@]} Markdown files"
[ $failures = 0 ]
