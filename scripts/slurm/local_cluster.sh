#!/usr/bin/env bash
# A single-node Slurm on this machine, to try scripts/slurm/ without a cluster (Debian 12, root):
# installs slurm-wlm and munge, writes /etc/slurm/slurm.conf for this host (all its cores, one
# partition "debug"), starts munged, slurmctld and slurmd. Idempotent; refuses to replace a
# slurm.conf it did not write.
set -euo pipefail
[ "$(id -u)" = 0 ] || { echo "local_cluster.sh: run as root" >&2; exit 1; }
missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
conf=/etc/slurm/slurm.conf marker="# written by momentbench scripts/slurm/local_cluster.sh"
if [ -e "$conf" ] && ! grep -qF "$marker" "$conf"; then
  echo "local_cluster.sh: $conf exists and was not written by this script; leaving it alone" >&2
  exit 1
fi
host=$(hostname -s)
memory=$(awk '/MemTotal/ {print int($2 / 1024) - 1024}' /proc/meminfo)
mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm /run/munge
chown munge:munge /run/munge
cat > "$conf" <<CONF
$marker
ClusterName=local
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
JobAcctGatherType=jobacct_gather/none
NodeName=$host CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
pgrep -x munged >/dev/null || munged --force
pgrep -x slurmctld >/dev/null || slurmctld
pgrep -x slurmd >/dev/null || slurmd
sleep 2
sinfo
