#!/usr/bin/env bash
# Validates every GLSL program variant of osgGlyphs with the Khronos reference compiler: writes the
# variants' stage sources with osgglyphs_shader_variants, links each variant's stages with
# glslangValidator -l, and fails naming every variant it rejects with glslang's messages. Usage:
#   check_shader_variants.sh VARIANTS_TOOL GLSLANG FOLDER [--full] [--inject-error VARIANT]
# --full: every combination of the options (about 19,000 programs, most of an hour), not all pairs.
# --inject-error VARIANT (a folder of variants.tsv, e.g. geometry-shader/0003): breaks that
# variant's last stage, then succeeds only if the check fails and names that variant alone.
set -euo pipefail
tool=$1 glslang=$2 folder=$3
shift 3
selection=--pairs inject=""
while (($#)); do
    case "$1" in
    --full) selection="" ;;
    --inject-error) inject=$2; shift ;;
    *) echo "check_shader_variants: unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
if ! command -v "$glslang" >/dev/null; then
    echo "check_shader_variants: FAIL: the Khronos reference compiler $glslang is missing (Debian: glslang-tools)" >&2
    exit 1
fi

rm -rf "$folder" && mkdir -p "$folder"
"$tool" $selection "$folder"
if [[ -n "$inject" ]]; then
    stage=$(ls "$folder/$inject"/* | tail -n 1)
    printf '\nthis line is not GLSL;\n' >>"$stage"
    echo "check_shader_variants: injected an error into $stage"
fi

failed=() warnings=""
while IFS=$'\t' read -r dir program defines note; do
    if ! log=$("$glslang" -l "$folder/$dir"/* 2>&1); then
        failed+=("$dir")
        echo "FAIL $dir: '$program' with [${defines}]${note:+ ($note)}:"
        grep -E 'ERROR' <<<"$log" | sed 's/^/    /'
    fi
    warnings+=$(grep -E '^WARNING' <<<"$log" || true)$'\n'
done <"$folder/variants.tsv"
echo "check_shader_variants: glslang warnings (each once):"
sort -u <<<"$warnings" | sed '/^$/d; s/^/    /'
echo "check_shader_variants: $(wc -l <"$folder/variants.tsv") variants, ${#failed[@]} rejected"

if [[ -n "$inject" ]]; then
    [[ "${failed[*]}" == "$inject" ]] && exit 0
    echo "check_shader_variants: FAIL: the broken variant $inject was not reported alone (rejected: ${failed[*]:-none})"
    exit 1
fi
((${#failed[@]} == 0))
