#!/usr/bin/env bash
# scripts/slurm-local.sh - a one-node Slurm cluster on this machine, for
# testing the sweep's Slurm path (tests/cli_sweep.sh) and for CI.
# Installs Debian's slurm-wlm and munge (as root), writes a minimal
# slurm.conf (node "localhost" with this machine's cores and memory, no
# cgroups, linuxproc process tracking), and starts munged, slurmctld and
# slurmd. Idempotent: a running cluster is left alone; running it again
# after a reboot starts the daemons again. `--stop` stops them.
set -euo pipefail

say() { printf 'slurm-local: %s\n' "$*" >&2; }
die() { printf 'slurm-local: %s\n' "$*" >&2; exit 2; }

[ "$(id -u)" = 0 ] || die "run as root (it installs packages and starts daemons)"
CONF_DIR=/etc/slurm
STATE=/var/spool/slurmctld
SPOOL=/var/spool/slurmd
LOGS=/var/log/slurm

if [ "${1:-}" = --stop ]; then
  for d in slurmd slurmctld munged; do
    if pid="$(pgrep -x "$d")"; then
      mapfile -t pids <<<"$pid"   # one daemon may run as several processes
      kill "${pids[@]}" && say "stopped $d (${pids[*]})"
    fi
  done
  exit 0
fi

install() {
  local missing="" p
  for p in slurm-wlm munge; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=" $p"
  done
  [ -z "$missing" ] && return 0
  say "installing$missing"
  DEBIAN_FRONTEND=noninteractive apt-get update -qq >/dev/null
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing >/dev/null
}

write_conf() {
  local cpus mem
  cpus="$(nproc)"
  mem="$(awk '/MemTotal/ {print int($2 / 1024 * 0.9)}' /proc/meminfo)"   # MB, leave the OS some
  mkdir -p "$CONF_DIR" "$STATE" "$SPOOL" "$LOGS"
  chown slurm: "$STATE" "$LOGS" 2>/dev/null || true
  local tmp
  tmp="$(mktemp "$CONF_DIR/.slurm.conf.XXXXXX")"
  cat >"$tmp" <<EOF
# One-node cluster written by noiselab's scripts/slurm-local.sh.
ClusterName=noiselab
SlurmctldHost=localhost
SlurmUser=slurm
AuthType=auth/munge
StateSaveLocation=$STATE
SlurmdSpoolDir=$SPOOL
SlurmctldLogFile=$LOGS/slurmctld.log
SlurmdLogFile=$LOGS/slurmd.log
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
# No cgroups (containers often lack them): plain process tracking.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
SchedulerType=sched/backfill
ReturnToService=2
MaxArraySize=100001
NodeName=localhost CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
  chmod 644 "$tmp"
  if cmp -s "$tmp" "$CONF_DIR/slurm.conf"; then rm -f "$tmp"; else mv "$tmp" "$CONF_DIR/slurm.conf"; say "wrote $CONF_DIR/slurm.conf"; fi
}

start_munge() {
  if [ ! -s /etc/munge/munge.key ]; then
    mkdir -p /etc/munge
    if command -v mungekey >/dev/null; then mungekey --create --force >/dev/null
    else dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none; fi
    chown munge: /etc/munge/munge.key; chmod 400 /etc/munge/munge.key
  fi
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge: /run/munge /var/log/munge /var/lib/munge
  pgrep -x munged >/dev/null && return 0
  su -s /bin/sh munge -c munged || runuser -u munge -- munged || die "munged did not start"
  say "started munged"
}

start_daemon() {   # NAME ARGS...
  local d="$1"; shift
  pgrep -x "$d" >/dev/null && return 0
  "$d" "$@" || die "$d did not start (see $LOGS/$d.log)"
  say "started $d"
}

wait_idle() {
  local i
  for i in $(seq 1 30); do
    if sinfo -h -o '%t' 2>/dev/null | grep -Eq '^(idle|mix|alloc)'; then say "cluster up: $(sinfo -h -o '%P %D %t %c cpus %m MB' | head -n 1)"; return 0; fi
    if [ "$i" = 5 ]; then scontrol update NodeName=localhost State=RESUME 2>/dev/null || true; fi
    sleep 1
  done
  sinfo >&2 || true
  tail -n 5 "$LOGS/slurmctld.log" "$LOGS/slurmd.log" >&2 2>/dev/null || true
  die "the node did not become idle in 30 s"
}

install
write_conf
start_munge
start_daemon slurmctld
start_daemon slurmd
wait_idle
