#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# tools/track/tests/run.sh - one command-line test of mtt-track (ctest cli.CASE).
#
#   sh run.sh MTT_TRACK DATA_DIR WORK_DIR CASE
#
# MTT_TRACK is the built program, DATA_DIR this directory (the test files),
# WORK_DIR a scratch directory of this case (emptied first).  Each bad-input
# case asserts the exit code, that stderr is exactly one line naming the
# file, line (or JSON key) and field, and that no tracks file, not even a
# temporary one, is left behind.  POSIX sh and awk only.
set -u

if [ $# -ne 4 ]; then
    echo "usage: sh run.sh MTT_TRACK DATA_DIR WORK_DIR CASE" >&2
    exit 2
fi
bin=$1
data=$2
work=$3
case=$4

rm -rf "$work" && mkdir -p "$work" || exit 1
out="$work/out.tracks.csv"
header='scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy'
rc=0

fail() {
    echo "FAIL cli.$case: $*" >&2
    if [ -s "$work/stderr" ]; then sed 's/^/  stderr| /' "$work/stderr" >&2; fi
    if [ -s "$work/stdout" ]; then sed 's/^/  stdout| /' "$work/stdout" | head -n 20 >&2; fi
    exit 1
}

# run ARGS...: run mtt-track, keep stdout, stderr and the exit code in rc.
run() {
    "$bin" "$@" >"$work/stdout" 2>"$work/stderr"
    rc=$?
}

no_temp() {
    for f in "$out".tmp.*; do
        if [ -e "$f" ]; then fail "temporary file left behind: $f"; fi
    done
}

no_output() {
    if [ -e "$out" ]; then fail "a tracks file was left behind after a failure"; fi
    no_temp
}

one_line_stderr() {
    n=$(wc -l <"$work/stderr")
    [ "$n" -eq 1 ] || fail "expected exactly one line on stderr, got $n"
}

stderr_has() {
    grep -F -q -- "$1" "$work/stderr" || fail "stderr lacks: $1"
}

stdout_has() {
    grep -F -q -- "$1" "$work/stdout" || fail "stdout lacks: $1"
}

# expect_fail CODE MESSAGE CONFIG DETECTIONS [ARGS...]: a run that must fail
# with exit CODE and one stderr line containing MESSAGE, leaving no output.
expect_fail() {
    want=$1
    msg=$2
    cfg=$3
    det=$4
    shift 4
    rm -f "$out"
    run --config "$cfg" --detections "$det" --tracks "$out" "$@"
    [ "$rc" -eq "$want" ] || fail "exit code $rc, expected $want"
    one_line_stderr
    stderr_has "mtt-track: "
    stderr_has "$msg"
    no_output
}

# det_fail NAME MESSAGE: detections file NAME.det.csv must be rejected.
det_fail() {
    expect_fail 2 "$1.det.csv:$2" "$data/empty.json" "$data/$1.det.csv"
}

# cfg_fail NAME MESSAGE: settings file NAME.json must be rejected.
# cfg_columns CFG EXTRA BAD_ROW MESSAGE: CFG runs; the tracks header is the
# twelve columns then EXTRA; no row matches the awk condition BAD_ROW.
cfg_columns() {
    rm -f "$out"
    run --config "$data/$1.json" --detections "$data/valid.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    [ "$(head -n 1 "$out")" = "scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy,$2" ] ||
        fail "header $(head -n 1 "$out")"
    awk -F, "NR > 1 && ($3) { bad = 1 } END { exit bad }" "$out" || fail "$4"
}

cfg_fail() {
    expect_fail 2 "$1.json: $2" "$data/$1.json" "$data/valid.det.csv"
}

# imm_ok CONFIG N: motion = imm runs; the tracks file gains mu_0 .. mu_{N-1},
# the model probabilities, summing to 1 on every row (docs/FORMATS.md).
imm_ok() {
    mu=$(awk -v n="$2" 'BEGIN { for (j = 0; j < n; ++j) printf "%smu_%d", (j ? "," : ""), j }')
    sum=$(awk -v n="$2" 'BEGIN { s = "$13"; for (j = 14; j < 13 + n; ++j) s = s " + $" j; print s }')
    cfg_columns "$1" "$mu" "NF != $((12 + $2)) || $sum < 0.9999 || $sum > 1.0001" \
        "a row without $2 model probabilities summing to 1"
}

# expect_ok ARGS...: a run that must succeed silently and write the tracks.
expect_ok() {
    rm -f "$out"
    run --config "$data/valid.json" --detections "$data/valid.det.csv" --tracks "$out" "$@"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    [ -f "$out" ] || fail "no tracks file written"
    no_temp
    [ "$(head -n 1 "$out")" = "$header" ] || fail "bad header: $(head -n 1 "$out")"
    rows=$(($(wc -l <"$out") - 1))
    [ "$rows" -gt 0 ] || fail "no track rows"
}

# Every row well-formed: 12 fields, known status, existence in [0, 1],
# pxx, pyy > 0, the time of the scan (time = scan in valid.det.csv).
check_rows() {
    awk -F, 'NR > 1 {
        if (NF != 12) { print "line " NR ": " NF " fields"; bad = 1 }
        if ($4 != "tentative" && $4 != "confirmed") { print "line " NR ": status " $4; bad = 1 }
        if ($9 + 0 < 0 || $9 + 0 > 1) { print "line " NR ": existence " $9; bad = 1 }
        if ($10 + 0 <= 0 || $12 + 0 <= 0) { print "line " NR ": covariance"; bad = 1 }
        if ($2 + 0 != $1 + 0) { print "line " NR ": time " $2 " for scan " $1; bad = 1 }
    } END { exit bad }' "$1" >"$work/check" || fail "malformed rows: $(head -n 3 "$work/check")"
}

# confirmed_near FILE SCAN X Y TOL: a confirmed track within TOL of (X, Y).
confirmed_near() {
    awk -F, -v s="$2" -v x="$3" -v y="$4" -v tol="$5" '
        NR > 1 && $1 == s && $4 == "confirmed" {
            dx = $5 - x; dy = $6 - y
            if (dx * dx + dy * dy <= tol * tol) ok = 1
        } END { exit !ok }' "$1"
}

# polar_ok CFG DET: CFG.json on DET.det.csv (valid.det.csv's target seen
# from (0, 0), or with its own covariances) runs cleanly with a confirmed
# track on the target at scan 11.
polar_ok() {
    rm -f "$out"
    run --config "$data/$1.json" --detections "$data/$2.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    [ ! -s "$work/stderr" ] || fail "stderr not empty on success"
    confirmed_near "$out" 11 111 50 1.5 ||
        fail "no confirmed track near the target (111, 50) at scan 11"
}

case "$case" in
# ---- usage ---------------------------------------------------------------
help)
    run --help
    [ "$rc" -eq 0 ] || fail "--help exit code $rc"
    for opt in --config --detections --tracks --tentative --confirmed-only --stats \
               --help --version --list-settings docs/FORMATS.md; do
        stdout_has "$opt"
    done
    [ ! -s "$work/stderr" ] || fail "--help wrote to stderr"
    ;;
list_settings)
    run --list-settings
    [ "$rc" -eq 0 ] || fail "--list-settings exit code $rc"
    [ ! -s "$work/stderr" ] || fail "--list-settings wrote to stderr"
    [ "$(head -n 1 "$work/stdout")" = "| key | type | range | default | meaning | tier |" ] ||
        fail "bad table header: $(head -n 1 "$work/stdout")"
    stdout_has "| \`pd\` | number | in (0, 1] | 0.9 | "
    stdout_has "| \`meas_sigma\` | 2 numbers | each in [1e-9, 1e9] | [1, 1] | "
    stdout_has "| \`terminate_threshold\` | number | in [0, 1); below confirm_threshold | 0.01 | "
    stdout_has "| \`initial_tracks\` | list | "
    stdout_has " | probability of detection PD | sensor |"
    # one row per key of the library's table, plus the header, rule and initial_tracks
    [ "$(grep -c '^| `' "$work/stdout")" -eq 55 ] || fail "expected 55 key rows"
    ;;
version)
    run --version
    [ "$rc" -eq 0 ] || fail "--version exit code $rc"
    grep -E -q '^mtt-track 0\.1\.0 \(mtt_real=(float|double|fixed)\)$' "$work/stdout" ||
        fail "bad version line: $(cat "$work/stdout")"
    ;;
usage_missing_option)
    run --config "$data/valid.json" --detections "$data/valid.det.csv"
    [ "$rc" -eq 2 ] || fail "exit code $rc, expected 2"
    one_line_stderr
    stderr_has "missing option '--tracks'"
    ;;
usage_unknown_option)
    expect_fail 2 "unknown option '--frobnicate'" "$data/valid.json" "$data/valid.det.csv" \
        --frobnicate
    ;;
usage_both_filters)
    expect_fail 2 "exclude each other" "$data/valid.json" "$data/valid.det.csv" \
        --tentative --confirmed-only
    ;;

# ---- valid runs ------------------------------------------------------------
valid)
    expect_ok
    [ ! -s "$work/stderr" ] || fail "stderr not empty on success"
    check_rows "$out"
    # the empty scan 5 was still run: the target's track is there
    awk -F, '$1 == 5 { n++ } END { exit !n }' "$out" || fail "no rows after the empty scan 5"
    confirmed_near "$out" 11 111 50 1.5 ||
        fail "no confirmed track near the target (111, 50) at scan 11"
    # no confirmed track on clutter: every confirmed row is near the target
    awk -F, 'NR > 1 && $4 == "confirmed" {
        dx = $5 - (100 + $1); dy = $6 - 50
        if (dx * dx + dy * dy > 9) { print; bad = 1 }
    } END { exit bad }' "$out" >"$work/check" ||
        fail "a confirmed track away from the target: $(head -n 1 "$work/check")"
    ;;
valid_confirmed_only)
    expect_ok
    all=$rows
    expect_ok --confirmed-only
    awk -F, 'NR > 1 && $4 != "confirmed" { bad = 1 } END { exit bad }' "$out" ||
        fail "--confirmed-only wrote a tentative track"
    [ "$rows" -le "$all" ] || fail "--confirmed-only wrote more rows ($rows) than all ($all)"
    confirmed_near "$out" 11 111 50 1.5 || fail "the target's confirmed track is missing"
    expect_ok --tentative
    [ "$rows" -eq "$all" ] || fail "--tentative wrote $rows rows, the default $all"
    ;;
valid_stats)
    expect_ok --stats
    stderr_has "12 frames"
    stderr_has "births"
    stderr_has "confirmations"
    stderr_has "deletions"
    stderr_has "merges"
    stderr_has "dropped"
    ;;
valid_deterministic)
    expect_ok
    mv "$out" "$work/first.csv"
    expect_ok
    cmp -s "$out" "$work/first.csv" || fail "two runs wrote different tracks"
    ;;
valid_crlf)
    # CRLF line ends, a byte order mark and blanks around fields read the same.
    expect_ok
    mv "$out" "$work/lf.csv"
    awk 'BEGIN { printf "\357\273\277" }
         /^[0-9]/ { gsub(/,/, " , ") } { printf "%s\r\n", $0 }' \
        "$data/valid.det.csv" >"$work/crlf.det.csv"
    run --config "$data/valid.json" --detections "$work/crlf.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc on a CRLF file"
    cmp -s "$out" "$work/lf.csv" || fail "a CRLF file gave other tracks than LF"
    ;;
seeded)
    rm -f "$out"
    run --config "$data/seeded.json" --detections "$data/valid.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc"
    # both seeds are confirmed tracks 0 and 1 from scan 0; initiate is false,
    # so no other identity ever appears
    awk -F, '$1 == 0 && $3 == 0 && $4 == "confirmed" { a = 1 }
             $1 == 0 && $3 == 1 && $4 == "confirmed" { b = 1 }
             NR > 1 && $3 > 1 { bad = 1 }
             END { exit !(a && b && !bad) }' "$out" ||
        fail "initial tracks 0 and 1 not confirmed at scan 0, or a track was born"
    awk -F, '$1 == 11 && $3 == 0 { dx = $5 - 111; dy = $6 - 50; ok = dx * dx + dy * dy <= 2.25 }
             END { exit !ok }' "$out" || fail "seeded track 0 did not follow the target"
    ;;
many_meas)
    # 600 detections in one scan: more than MTT_MAX_MEAS by default
    awk 'BEGIN {
        print "scan,time,x,y,amplitude"
        for (s = 0; s < 3; s++) {
            print s "," s "," 100 + s "," 50 "," 20
            for (i = 0; i < 600; i++)
                print s "," s "," (i * 37 + s * 11) % 997 "," (i * 53 + s * 7) % 991 "," (i % 7) / 7
        }
    }' >"$work/many.det.csv"
    rm -f "$out"
    run --config "$data/valid.json" --detections "$work/many.det.csv" --tracks "$out" --stats
    [ "$rc" -eq 0 ] || fail "exit code $rc"
    stderr_has "1803 detections in"
    [ "$(head -n 1 "$out")" = "$header" ] || fail "bad header"
    # the strongest detections are kept: the target (amplitude 20) has a track
    awk -F, '$1 == 2 { dx = $5 - 102; dy = $6 - 50; if (dx * dx + dy * dy <= 1) ok = 1 }
             END { exit !ok }' "$out" || fail "no track on the strong target among 600 clutter"
    ;;
no_scans)
    printf '# nothing\nscan,time,x,y,amplitude\n' >"$work/none.det.csv"
    rm -f "$out"
    run --config "$data/seeded.json" --detections "$work/none.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc"
    [ "$(cat "$out")" = "$header" ] || fail "expected the header alone"
    ;;
same_file)
    cp "$data/valid.det.csv" "$work/d.det.csv"
    run --config "$data/valid.json" --detections "$work/d.det.csv" --tracks "$work/d.det.csv"
    [ "$rc" -eq 2 ] || fail "exit code $rc, expected 2"
    one_line_stderr
    stderr_has "same file"
    cmp -s "$work/d.det.csv" "$data/valid.det.csv" || fail "the detections file was changed"
    ;;
existing_output_kept)
    echo "old" >"$out"
    run --config "$data/cfg_out_of_range.json" --detections "$data/valid.det.csv" --tracks "$out"
    [ "$rc" -eq 2 ] || fail "exit code $rc, expected 2"
    [ "$(cat "$out")" = "old" ] || fail "an existing tracks file was changed by a failed run"
    no_temp
    ;;

# ---- bad detections --------------------------------------------------------
det_missing_file)
    expect_fail 2 "no_such_file.det.csv: cannot open" "$data/empty.json" \
        "$work/no_such_file.det.csv"
    ;;
det_missing_column)     det_fail det_missing_column "2: field 'y': missing column" ;;
det_renamed_column)     det_fail det_renamed_column "1: field 'amplitude': missing column" ;;
det_extra_column)       det_fail det_extra_column "1: field 'snr': unexpected extra column" ;;
det_non_numeric)        det_fail det_non_numeric "3: field 'x': 'abc' is not a finite number" ;;
det_nan)                det_fail det_nan "5: field 'y': 'nan' is not allowed" ;;
det_inf)                det_fail det_inf "2: field 'amplitude': 'inf' is not allowed" ;;
det_out_of_range)       expect_fail 2 "det_out_of_range.det.csv:11: field 'y': '-5e6' is outside this build's range [-" \
                            "$data/valid.json" "$data/det_out_of_range.det.csv"
                        stderr_has "--skip-out-of-range skips" ;;
det_out_of_range_skip)
    rm -f "$out"
    run --config "$data/valid.json" --detections "$data/det_out_of_range.det.csv" --tracks "$out" \
        --skip-out-of-range
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    [ -f "$out" ] || fail "no tracks file written"
    one_line_stderr
    stderr_has "det_out_of_range.det.csv: 1 detections outside this build's range skipped (1 counted by the tracker, meas_out_of_range)"
    run --config "$data/valid.json" --detections "$data/det_out_of_range.det.csv" --tracks "$out" \
        --skip-out-of-range --stats
    [ "$rc" -eq 0 ] || fail "exit code $rc with --stats, expected 0"
    stderr_has "stats: 1 detections outside this build's range (skipped)"
    stderr_has " 0 bad (skipped)"
    ;;
det_trailing_garbage)   det_fail det_trailing_garbage "3: field 'x': '4.5e1x' is not" ;;
det_decreasing_time)    det_fail det_decreasing_time "4: field 'time': '1.5' is not later" ;;
det_scan_time_mismatch) det_fail det_scan_time_mismatch "4: field 'time': '1.25' differs" ;;
det_decreasing_scan)    det_fail det_decreasing_scan "4: field 'scan': 1 after scan 2" ;;
det_negative_amplitude) det_fail det_negative_amplitude "3: field 'amplitude': '-0.5' is negative" ;;
det_half_empty)         det_fail det_half_empty "3: field 'x': missing value" ;;
det_field_count)        det_fail det_field_count "3: field 'amplitude': missing" ;;
det_mixed_empty_scan)   det_fail det_mixed_empty_scan "4: field 'x': scan 1 has both" ;;
det_cov_missing)        det_fail det_cov_missing "3: field 'r_yy': missing value" ;;
det_cov_not_pd)         det_fail det_cov_not_pd "3: field 'r_xy': '5' makes the covariance not positive definite" ;;
det_cov_field_count)    det_fail det_cov_field_count "3: field 'r_xx': missing" ;;
valid_cov_empty)
    # the covariance columns left empty: meas_sigma's, the tracks of valid.det.csv
    run --config "$data/empty.json" --detections "$data/valid.det.csv" --tracks "$work/a.csv"
    [ "$rc" -eq 0 ] || fail "exit code $rc on valid.det.csv"
    run --config "$data/empty.json" --detections "$data/valid_cov_empty.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    cmp -s "$out" "$work/a.csv" || fail "tracks differ from valid.det.csv's"
    ;;
cov_valid)
    # a covariance per detection (ALGORITHMS.md §3.1; fixed point: the
    # radar scale's build, docs/FIXED_POINT.md §5): read and tracked
    polar_ok valid valid_cov
    run --config "$data/valid.json" --detections "$data/valid.det.csv" --tracks "$work/a.csv"
    [ "$rc" -eq 0 ] || fail "exit code $rc on valid.det.csv"
    ! cmp -s "$out" "$work/a.csv" || fail "the own covariances changed nothing"
    ;;
cov_unsupported)
    # a build without MTT_WITH_MEAS_COV (the fixed point's default scale, the firmware configuration)
    expect_fail 2 "valid_cov.det.csv:5: field 'r_xx': scan 0: a covariance per detection is not available here" \
        "$data/valid.json" "$data/valid_cov.det.csv" ;;
det_cov_out_of_range)
    expect_fail 2 "det_cov_out_of_range.det.csv:16: field 'r_xx': the covariance (1e9, 0, 0.05) is outside this build's variance format" \
        "$data/valid.json" "$data/det_cov_out_of_range.det.csv"
    stderr_has "--skip-out-of-range skips"
    run --config "$data/valid.json" --detections "$data/det_cov_out_of_range.det.csv" --tracks "$out" \
        --skip-out-of-range --stats
    [ "$rc" -eq 0 ] || fail "exit code $rc with --skip-out-of-range, expected 0"
    stderr_has "det_cov_out_of_range.det.csv: 1 detections outside this build's range skipped (1 counted by the tracker, meas_out_of_range)"
    stderr_has " 0 bad (skipped)"
    ;;

polar_valid)
    # polar detections (ALGORITHMS.md §3.2): valid.det.csv seen from (0, 0)
    polar_ok polar polar
    ;;
det_polar_bad_range)    expect_fail 2 "det_polar_bad_range.det.csv:3: field 'range': '-3' must be > 0" \
                            "$data/polar.json" "$data/det_polar_bad_range.det.csv" ;;
det_polar_bearing)      expect_fail 2 "det_polar_bearing.det.csv:3: field 'bearing': 'north' is not a finite number" \
                            "$data/polar.json" "$data/det_polar_bearing.det.csv" ;;
det_polar_range_rate)   expect_fail 2 "polar.json: key 'range_rate_sigma': missing: " \
                            "$data/polar.json" "$data/det_polar_range_rate.det.csv" ;;
polar_range_rate_valid)
    # a range rate per detection: gated and updated with (ALGORITHMS.md §3.2)
    polar_ok polar_rr polar_rr
    # its velocity (1, 0) per scan to 0.2
    awk -F, '$1 == 11 && $4 == "confirmed" && ($7 - 1) ^ 2 + $8 ^ 2 < 0.04 { ok = 1 } END { exit !ok }' "$out" ||
        fail "the confirmed track's velocity at scan 11 is not (1, 0)"
    ;;
polar_split)
    # polar detections with split = true (ALGORITHMS.md §14.3): the split
    # modes take each converted detection's own R; p_split in every row
    polar_ok polar_split polar
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p_split") c = i; next }
             !c || $c == "" || $c < 0 || $c > 1 { exit 1 }' "$out" ||
        fail "a row without a split probability in [0, 1]"
    ;;
polar_split_modes)
    # a polar target that splits (polar_split.det.csv): the split modes run
    # on the converted detections' own R, P(split) of track 0 >= 0.9 at scan 14
    rm -f "$out"
    run --config "$data/polar_split.json" --detections "$data/polar_split.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p_split") c = i; next }
             $1 == 14 && $3 == 0 && $c >= 0.9 { ok = 1 } END { exit !ok }' "$out" ||
        fail "track 0 without P(split) >= 0.9 at scan 14"
    ;;
polar_split_range_rate)
    # the split modes take the range rates too (polar_split_rr.det.csv): the
    # child splits off track 0 and is confirmed near (129, 67) at scan 29
    rm -f "$out"
    run --config "$data/polar_split_rr.json" --detections "$data/polar_split_rr.det.csv" --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0"
    awk -F, '$1 == 29 && $4 == "confirmed" && $NF == "0" && ($5 - 129) ^ 2 + ($6 - 67) ^ 2 < 4 { ok = 1 }
             END { exit !ok }' "$out" || fail "no child of track 0 confirmed near (129, 67) at scan 29"
    ;;
det_polar_cartesian_settings)
    # the header names the form, the settings must agree
    expect_fail 2 "polar.det.csv:3: field 'range': the header is the polar (range,bearing) form but" \
        "$data/empty.json" "$data/polar.det.csv" ;;
det_cartesian_polar_settings)
    expect_fail 2 "valid.det.csv:4: field 'x': the header is the Cartesian (x,y) form but" \
        "$data/polar.json" "$data/valid.det.csv" ;;
cfg_polar_unsupported)  # values inside both fixed-point scales' formats, so that the refusal is the first error
                        expect_fail 2 "polar_fixed.json: key 'measurement': measurement = polar needs a floating-point build with MTT_WITH_MEAS_COV" \
                            "$data/polar_fixed.json" "$data/polar.det.csv" ;;

# ---- bad settings ------------------------------------------------------------
cfg_missing_file)
    expect_fail 2 "no_such_file.json: cannot open" "$work/no_such_file.json" \
        "$data/valid.det.csv"
    ;;
cfg_malformed)
    expect_fail 2 "cfg_malformed.json:3: malformed JSON" "$data/cfg_malformed.json" \
        "$data/valid.det.csv"
    ;;
cfg_not_object)         cfg_fail cfg_not_object "the settings must be a JSON object" ;;
cfg_unknown_key)        cfg_fail cfg_unknown_key "key 'pdd': unknown key (did you mean 'pd'?)" ;;
cfg_duplicate_key)      cfg_fail cfg_duplicate_key "key 'pd': given twice" ;;
cfg_wrong_type)         cfg_fail cfg_wrong_type "key 'pd': must be a number, found a string" ;;
cfg_wrong_type_bool)    cfg_fail cfg_wrong_type_bool "key 'initiate': must be true or false" ;;
cfg_out_of_range)       cfg_fail cfg_out_of_range "key 'pd': must be in (0, 1], found 1.5" ;;
cfg_fixed_format)       cfg_fail cfg_fixed_format "key 'clutter_density': must be >= 0 within its fixed-point format (this build holds |v| < "
                        stderr_has ", Q"
                        stderr_has "found 5" ;;
cfg_fixed_imm_ca)       cfg_fail cfg_fixed_imm_ca "key 'imm_models': this fixed-point build's IMM has cv models only: ca and ct need a floating-point build" ;;
cfg_fixed_max_accel)    cfg_fail cfg_fixed_max_accel "key 'max_accel': with process_psd not given, max_accel² (the process noise per unit of time) is a variance of this fixed-point build's format" ;;
cfg_sigma_out_of_range) cfg_fail cfg_sigma_out_of_range "key 'meas_sigma[1]': must be in [1e-9, 1e9], found -2" ;;
cfg_array_length)       cfg_fail cfg_array_length "key 'meas_sigma': must be an array of 2 numbers" ;;
cfg_bad_association)    cfg_fail cfg_bad_association "key 'association': unknown association 'lm-ihpdaa'" ;;
cfg_unsupported_association)
    # Every association mode is built: the former example of
    # an unsupported mode, jpda, now runs.
    rm -f "$out"
    run --config "$data/cfg_unsupported_association.json" --detections "$data/valid.det.csv" \
        --tracks "$out"
    [ "$rc" -eq 0 ] || fail "exit code $rc, expected 0 (jpda is built)"
    [ -f "$out" ] || fail "no tracks file written"
    ;;
cfg_bad_init_gate)      cfg_fail cfg_bad_init_gate "key 'init_gate': unknown init_gate 'circle' (expected one of: vmax, intensity)" ;;
cfg_intensity_subkey)   cfg_fail cfg_intensity_subkey "key 'intensity_gate.f3': unknown key" ;;
cfg_seed_missing_member) cfg_fail cfg_seed_missing_member "key 'initial_tracks[1].vy': missing" ;;
cfg_seed_bad_cov)
    cfg_fail cfg_seed_bad_cov "key 'initial_tracks[0].P': must be a symmetric positive definite"
    ;;
cfg_imm_unsupported)    cfg_fail cfg_imm_unsupported "key 'motion': motion = imm needs an association other than ihpda-2d and lm-ipda-all" ;;
cfg_imm_transition_size) cfg_fail cfg_imm_transition_size "key 'imm_transition': must be r rows of r (r models), each row summing to 1 (with 2 models in imm_models)" ;;
cfg_imm_bad_model)      cfg_fail cfg_imm_bad_model "key 'imm_models[0].model': unknown model 'cj' (expected one of: cv, ca, ct)" ;;
cfg_imm_valid)          imm_ok cfg_imm_valid 2 ;;
cfg_imm_ct_no_turn)     cfg_fail cfg_imm_ct_no_turn "key 'imm_models[1].turn_psd': missing (model ct needs its turn-rate noise)" ;;
cfg_imm_turn_not_ct)    cfg_fail cfg_imm_turn_not_ct "key 'imm_models[0].turn_psd': only model ct has a turn rate" ;;
cfg_imm_ct_valid)       imm_ok cfg_imm_ct_valid 3 ;; # CV, CA and a coordinated turn
cfg_split_unsupported)  cfg_fail cfg_split_unsupported "key 'split': split = true needs motion = imm with a cv model in imm_models" ;;
cfg_split_valid)
    # split = true: after mu_0, mu_1 the split probability and the parent column (docs/FORMATS.md)
    cfg_columns cfg_split_valid mu_0,mu_1,p_split,parent \
        'NF != 16 || $15 < 0 || $15 > 1' "a row without a split probability in [0, 1] and a parent column"
    ;;
*)
    echo "run.sh: unknown case '$case'" >&2
    exit 2
    ;;
esac
echo "PASS cli.$case"
exit 0
