"""The memory available to this process now, and the fraction of it any allocation plans
for: one home for the solvers (:mod:`contact.bem._memory`) and the file readers
(:mod:`surfmet.io._registry`), with no import beyond the standard library so that reading a
file does not load the solvers."""

from __future__ import annotations

import os

#: Fraction of the available memory a solve (or a read) may plan to use, so that the
#: out-of-memory killer never has to choose this process.
SAFETY = 0.8


def _meminfo_available() -> int | None:
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        return None
    return None


def _cgroup_available() -> int | None:
    try:
        with open("/sys/fs/cgroup/memory.max", encoding="ascii") as fh:
            limit = fh.read().strip()
        if limit == "max":
            return None
        with open("/sys/fs/cgroup/memory.current", encoding="ascii") as fh:
            used = int(fh.read().strip())
        return max(int(limit) - used, 0)
    except (OSError, ValueError):
        return None


def _address_space_available() -> int | None:
    """Room left under this process's address-space limit (``ulimit -v``), or None."""
    try:
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft == resource.RLIM_INFINITY:
            return None
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("VmSize:"):
                    return max(soft - int(line.split()[1]) * 1024, 0)
    except (ImportError, OSError, ValueError, IndexError):
        return None
    return None


def available_bytes() -> int | None:
    """Memory available to this process now (bytes), or None where it cannot be read.

    ``MemAvailable`` of ``/proc/meminfo`` (free memory plus reclaimable caches), bounded by
    the cgroup v2 limit and by the room left under an address-space limit (``ulimit -v``);
    elsewhere the free physical pages (``sysconf``).
    """
    found = [v for v in (_meminfo_available(), _cgroup_available(),
                         _address_space_available()) if v is not None]
    if not found:
        try:
            found = [os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")]
        except (ValueError, OSError, AttributeError):
            return None
    return min(found)
