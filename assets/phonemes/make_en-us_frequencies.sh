#!/bin/sh
# Recomputes en-us_frequencies.csv, the bundled American English phoneme frequency table, with
# `visemelab freq` from Ambrose Bierce's "The Devil's Dictionary" (1911, public domain) as shipped
# by Debian's dict-devil package (docs/phonemes.md explains the choice).
# Usage: assets/phonemes/make_en-us_frequencies.sh [path/to/visemelab]
set -eu
here=$(dirname "$0")
cli=${1:-build/app/visemelab}
source_file=/usr/share/dictd/devil.dict.dz
[ -f "$source_file" ] || { echo "missing $source_file: apt-get install dict-devil" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Drop dictd's header lines, and the part-of-speech abbreviation after each headword
# ("ABASEMENT, n.") that espeak-ng would spell out letter by letter.
zcat "$source_file" |
    sed -e '/^00-database/d' \
        -e 's/^\([A-Z][A-Z'"'"' -]*\), *\(n\|n\.pl\|adj\|adv\|v\|v\.t\|v\.i\|pro\|pron\|pp\|p\.p\|x\)\./\1./' \
        >"$tmp/devils-dictionary.txt"
"$cli" freq "$tmp/devils-dictionary.txt" --voice en-us --quiet --out "$here/en-us_frequencies.csv"
