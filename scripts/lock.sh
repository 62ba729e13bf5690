# scripts/lock.sh - one run at a time in a folder: sourced by scripts/noiselab
# (reproduce, DIR/.noiselab.lock) and scripts/sweep.sh (DIR/.lock).
# shellcheck shell=bash
#
# The lock is an exclusive flock on a file holding one line that names its
# holder: "pid P<TAB>since T<TAB>command C". The line is written into a new
# file, which is locked and only then linked under the lock's name (link
# fails when the name exists), so a run that finds the lock taken always
# reads a whole line: the winner of two runs started together never shows
# an empty file. A lock file whose flock is free was left by a run that has
# ended; the next run renames its own file over it.
#
# Descriptor 9 holds the lock, and every process the run starts inherits it,
# so the lock lasts until the run and all its processes have exited. A run
# killed outright (SIGKILL: no trap runs) would leave its experiments,
# gnuplot, or GNU parallel and its tasks running and writing into the folder
# with nobody to answer for them; a watchdog (lock_watch) stops them as soon
# as the run's shell is gone. They are the processes whose descriptor 9
# carries this flock (/proc/PID/fdinfo/9 lists the locks of the open file
# it refers to), so a later run, which opens the file anew, is never one.

# The pids whose descriptor 9 (with "any": any descriptor) holds the flock
# on inode INO, one a line.
lock_holders() {   # INO [any]
  local files=(/proc/[0-9]*/fdinfo/9)
  [ "${2:-}" != any ] || files=(/proc/[0-9]*/fdinfo/*)
  local re="^lock:[[:space:]]+[0-9]+: FLOCK .* [0-9a-f]+:[0-9a-f]+:$1 "
  grep -l -E "$re" "${files[@]}" 2>/dev/null |
    sed 's|^/proc/\([0-9]*\)/.*|\1|' | sort -un || true
}

# "pid P (COMMAND LINE)" for each pid given, comma-separated.
lock_describe() {   # PID...
  local p c out=""
  for p in "$@"; do
    c="$(tr '\0' ' ' <"/proc/$p/cmdline" 2>/dev/null | head -c 160)" || c=""
    [ -n "$c" ] || continue
    out+="${out:+, }pid $p (${c% })"
  done
  printf '%s' "$out"
}

# Does descriptor FD refer to the file now named PATH?
lock_same_file() {   # FD PATH
  [ "$(stat -L -c %d:%i "/dev/fd/$1" 2>/dev/null)" = "$(stat -c %d:%i "$2" 2>/dev/null)" ]
}

# Takes the lock LOCK for a run described by WHAT (its command line): 0 with
# descriptor 9 holding it and the watchdog started; 1 when another run holds
# it, LOCK_HOLDER then naming that run's pid and command (or, when that
# shell is gone, the processes it left that still hold the lock); 2 when the
# lock file cannot be made, LOCK_HOLDER saying why.
lock_take() {   # LOCK WHAT
  local lock="$1" what="$2" tmp k w held pid
  LOCK_HOLDER=""
  if ! tmp="$(mktemp "$lock.XXXXXX" 2>/dev/null)"; then
    LOCK_HOLDER="cannot make a file beside $lock"
    return 2
  fi
  if ! printf 'pid %s\tsince %s\tcommand %s\n' "$$" "$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$what" \
       >"$tmp"; then
    rm -f "$tmp"; LOCK_HOLDER="cannot write $tmp"; return 2
  fi
  chmod 0644 "$tmp"
  exec 9<"$tmp"
  flock -n 9   # a new file: nobody else can hold it
  for ((k = 0; k < 50; k++)); do
    if ln "$tmp" "$lock" 2>/dev/null; then
      rm -f "$tmp"; lock_watch "$lock"; return 0
    fi
    # A file system without hard links (vfat, some network shares): a rename
    # that never replaces (mv -n) does the same, the file keeping its lock.
    if [ ! -e "$lock" ] && mv -n "$tmp" "$lock" 2>/dev/null && [ ! -e "$tmp" ]; then
      lock_watch "$lock"; return 0
    fi
    { exec 8<"$lock"; } 2>/dev/null || continue   # removed or replaced meanwhile: again
    # A holder whose shell is gone: its watchdog is stopping the processes
    # it left (a few tenths of a second), so wait a little for them.
    for ((w = 0; w < 50; w++)); do
      held=1
      if flock -n 8; then
        held=0; break
      fi
      IFS= read -r LOCK_HOLDER </dev/fd/8 || true
      pid="${LOCK_HOLDER#pid }"; pid="${pid%%[!0-9]*}"
      # No pid: a lock not taken here (a user's flock); nothing to wait for.
      { [ -z "$pid" ] || kill -0 "$pid" 2>/dev/null; } && break
      lock_same_file 8 "$lock" || break
      sleep 0.1
    done
    if [ "$held" = 0 ]; then
      # Free: the run that made it has ended. Replaced only if the name
      # still means this file (another run may have replaced it first).
      if lock_same_file 8 "$lock" && mv -f "$tmp" "$lock"; then
        exec 8<&-; lock_watch "$lock"; return 0
      fi
      exec 8<&-; continue
    fi
    lock_same_file 8 "$lock" || { exec 8<&-; continue; }
    local left
    if [ -z "$pid" ]; then
      # shellcheck disable=SC2046  # one pid a word
      left="$(lock_describe $(lock_holders "$(stat -L -c %i /dev/fd/8)" any))"
      LOCK_HOLDER="held by ${left:-a process this user cannot see}"
    elif ! kill -0 "$pid" 2>/dev/null; then
      # shellcheck disable=SC2046  # one pid a word
      left="$(lock_describe $(lock_holders "$(stat -L -c %i /dev/fd/8)"))"
      # shellcheck disable=SC2046  # not a run's process (a user's flock)
      [ -n "$left" ] || left="$(lock_describe $(lock_holders "$(stat -L -c %i /dev/fd/8)" any))"
      LOCK_HOLDER+="; that run has ended but its processes still hold the lock: ${left:-none found}"
    fi
    LOCK_HOLDER="$(printf '%s' "$LOCK_HOLDER" | tr '\t' ' ' | head -c 600)"
    exec 8<&- 9<&-; rm -f "$tmp"
    return 1
  done
  exec 9<&-; rm -f "$tmp"
  LOCK_HOLDER="$lock keeps changing hands"
  return 1
}

# The watchdog of a run holding LOCK on descriptor 9: a process of its own
# (not a child the run's `wait` would wait for) that waits for the run's
# shell to end. A shell that exits by itself stops it first (lock_release,
# from the EXIT trap); a shell killed outright cannot, so the watchdog stops
# every process still holding the lock: SIGTERM (each removes its
# temporaries), and SIGKILL after 3 s.
lock_watch() {   # LOCK
  local owner=$$ ino
  ino="$(stat -c %i "$1")"
  LOCK_WATCHDOG="$(
    (
      set +e
      trap '' INT HUP
      tail --pid="$owner" -s 0.2 -f /dev/null
      for ((t = 0; t < 100; t++)); do
        flock -n 8 && exit 0
        # shellcheck disable=SC2046  # one pid a word
        kill -s "$([ "$t" -lt 30 ] && echo TERM || echo KILL)" $(lock_holders "$ino") 2>/dev/null
        sleep 0.1
      done
    ) 9<&- 8<"$1" </dev/null >/dev/null 2>&1 &
    echo $!
  )"
  trap lock_release EXIT
}

# Stops the watchdog; the lock itself goes with the last process holding 9.
lock_release() {
  [ -z "${LOCK_WATCHDOG:-}" ] || kill "$LOCK_WATCHDOG" 2>/dev/null || true
  LOCK_WATCHDOG=""
}
