# Fuzzing helpers shared by scripts/fuzz and scripts/test (docs/testing.md). Source after
# common.sh and build_fuzz. Targets: scene (tests/fuzz/scene_fuzz.cpp), link (link_fuzz.cpp).
# Binaries from build_fuzz ($BUILD/asan); seeds, corpora, findings and logs in $FUZZ_BUILD.
FUZZ_BUILD="$BUILD/fuzz"
FUZZ_TARGETS=(scene link)
# Inputs up to 64 KiB (the link bomb seed is 63 KiB). -timeout: the examples take 2-400 ms
# per input here, but a valid patch whose periodic data is not smooth makes the reference
# method double its Fourier modes up to 1024 (~8 s CPU under this instrumentation, found by
# fuzzing), and a scene may hold 64 patches; 60 s is a hang or a real blow-up, not a large
# scene. 2 GiB resident (or in one malloc) is a finding.
FUZZ_FLAGS=(-max_len=65536 -timeout=60 -rss_limit_mb=2048)

fuzz_bin() { echo "$BUILD/asan/tests/fuzz/$1_fuzz"; }

# fuzz_seeds TARGET: (re)writes $FUZZ_BUILD/seeds-TARGET from what exists now.
fuzz_seeds() {
  rm -rf "$FUZZ_BUILD/seeds-$1"
  mkdir -p "$FUZZ_BUILD"
  node "$ROOT/tests/fuzz/seeds.mjs" "$1" "$FUZZ_BUILD/seeds-$1" >/dev/null
}

# fuzz_replay TARGET: runs every file of the regression corpus tests/fuzz/corpus/TARGET/
# (findings included: a finding fails until the core is fixed) and every seed once.
fuzz_replay() {
  local target=$1 bin log
  bin="$(fuzz_bin "$target")"
  log="$FUZZ_BUILD/replay-$target.log"
  fuzz_seeds "$target" || return 1
  local files=() f
  for f in "$ROOT/tests/fuzz/corpus/$target"/* "$FUZZ_BUILD/seeds-$target"/*; do
    [ -f "$f" ] && files+=("$f")
  done
  if "$bin" "${FUZZ_FLAGS[@]}" "${files[@]}" >"$log" 2>&1; then
    echo "replay $target: ${#files[@]} inputs, no findings"
    return 0
  fi
  # One process stops at the first failure; name every failing input.
  local failed=0
  for f in "${files[@]}"; do
    if ! "$bin" "${FUZZ_FLAGS[@]}" "$f" >"$log.one" 2>&1; then
      failed=$((failed + 1))
      echo "replay $target: FAILED on ${f#"$ROOT"/}"
      grep -m1 -E 'ERROR: |runtime error: |^scene_fuzz: |^link_fuzz: |terminate called|ALARM|out-of-memory' "$log.one" | sed 's/^/    /'
      cp "$log.one" "$FUZZ_BUILD/replay-$target-$(basename "$f").log"
    fi
  done
  echo "replay $target: $failed of ${#files[@]} inputs FAILED (logs: $FUZZ_BUILD/replay-$target-*.log)"
  return 1
}

# fuzz_run TARGET SECONDS: fuzzes from the seeds plus the regression corpus (without its
# finding-* files, which the replay covers: they would stop the run at once) into the
# scratch corpus $FUZZ_BUILD/corpus-TARGET, kept between runs. Crashes, timeouts and
# out-of-memory inputs are written to $FUZZ_BUILD/findings-TARGET/; any new one fails.
# Prints the run's wall time, runs, exec/s and corpus growth.
fuzz_run() {
  local target=$1 seconds=$2 bin work findings log stamp
  bin="$(fuzz_bin "$target")"
  work="$FUZZ_BUILD/corpus-$target"
  findings="$FUZZ_BUILD/findings-$target"
  log="$FUZZ_BUILD/fuzz-$target.log"
  stamp="$FUZZ_BUILD/.fuzz-$target-start"
  mkdir -p "$work" "$findings"
  fuzz_seeds "$target" || return 1
  cp "$FUZZ_BUILD/seeds-$target"/* "$work"/
  local f
  for f in "$ROOT/tests/fuzz/corpus/$target"/*; do
    [ -f "$f" ] && [[ "$(basename "$f")" != finding-* ]] && cp "$f" "$work"/
  done
  touch "$stamp"
  local start=$SECONDS
  "$bin" "${FUZZ_FLAGS[@]}" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="$findings/" "$work" >"$log" 2>&1
  local rc=$?
  local execs speed added
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  added=$(sed -n 's/^stat::new_units_added: *//p' "$log")
  # slow-unit-* (past libFuzzer's -report_slow_units, 10 s) are kept for a look, not failed on.
  local -a new slow
  mapfile -t new < <(find "$findings" -type f -newer "$stamp" ! -name 'slow-unit-*')
  mapfile -t slow < <(find "$findings" -type f -newer "$stamp" -name 'slow-unit-*')
  echo "fuzz $target: $((SECONDS - start)) s, ${execs:-?} runs, ${speed:-?} exec/s, ${added:-?} new corpus inputs," \
    "corpus $(find "$work" -type f | wc -l) files"
  for f in "${slow[@]}"; do echo "fuzz $target: slow input (over 10 s, not a failure): $f"; done
  if [ "$rc" -ne 0 ] || [ "${#new[@]}" -gt 0 ]; then
    echo "fuzz $target: FINDING (libFuzzer exit $rc; log $log)"
    grep -m1 -E 'ERROR: |runtime error: |^scene_fuzz: |^link_fuzz: |terminate called|ALARM|out-of-memory' "$log" | sed 's/^/    /'
    for f in "${new[@]}"; do echo "    input: $f"; done
    echo "    replay: $bin FILE; keep it as tests/fuzz/corpus/$target/finding-WHAT"
    return 1
  fi
}
