#!/usr/bin/env python3
"""What the first write to fresh memory costs on this machine (issue 16): a solver's first solve lays out tables
no page of which the process has touched before (the far field's two layouts, 0.43 GB at 10^5 balls), and a later
solve reuses them. This times that first touch apart from heliostand, in seconds a GiB, for memory mapped in 4 KiB
pages and for memory advised to be huge pages (MADV_HUGEPAGE, 2 MiB), each

  - the first time the process maps that much (the memory comes from what the machine holds free),
  - right after the same size was unmapped (memory the kernel freed a moment before),
  - after a pause of --pause seconds (on a virtual machine whose balloon reports free memory to its host, the host
    takes such memory back within seconds, and a touch must have it backed again);

and for 4 KiB pages made resident before the first write, in one call for all of them (Linux's MADV_POPULATE_WRITE,
as heliostand does for its kept OpenCL buffers on a CPU device): that call's seconds a GiB come first on those lines.

    validation/bench/first_touch.py --mib 1024 --pause 5

One line a measurement, "PAGES WHEN: S s a GiB (first pass), S s a GiB (second pass)"; the second pass writes the same
pages again, already mapped, so it shows what a write costs without the faults. Timings vary with the machine and the
hour: compare lines of one run. docs/performance.md "What a first touch costs here, measured apart" has this
machine's figures.
"""
import argparse
import mmap
import time

GIB = float(1 << 30)
PAGE = 4096
MADV_POPULATE_WRITE = getattr(mmap, "MADV_POPULATE_WRITE", 23)  # Linux 5.14; Debian 12's Python does not name it


def whole_number(minimum):
    """A whole number of at least `minimum`, as heliostand's own counts are checked."""
    def check(text):
        if not text.isdigit() or int(text) < minimum:
            raise argparse.ArgumentTypeError(f"a whole number >= {minimum} is expected, got {text}")
        return int(text)
    return check


def touch(size, huge, resident_first=False):
    """Seconds a GiB of the first and the second write to every 4 KiB page of `size` freshly mapped bytes, after
    the call that makes them resident if `resident_first` (its seconds a GiB first)."""
    memory = mmap.mmap(-1, size, flags=mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS)
    try:
        if huge:
            memory.madvise(mmap.MADV_HUGEPAGE)
        seconds = []
        if resident_first:
            start = time.perf_counter()
            memory.madvise(MADV_POPULATE_WRITE)
            seconds.append((time.perf_counter() - start) * GIB / size)
        for value in (1, 2):
            start = time.perf_counter()
            for offset in range(0, size, PAGE):
                memory[offset] = value
            seconds.append((time.perf_counter() - start) * GIB / size)
        return seconds
    finally:
        memory.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mib", type=whole_number(1), default=1024, help="memory touched each time, MiB (default 1024)")
    parser.add_argument("--pause", type=whole_number(0), default=5,
                        help="seconds to wait before the last measurements (default 5)")
    arguments = parser.parse_args()
    size = arguments.mib << 20
    kinds = [("4 KiB pages", False)] + ([("huge pages", True)] if hasattr(mmap, "MADV_HUGEPAGE") else [])
    for name, huge in kinds:
        for when in ("fresh", "right after unmapping", "right after unmapping", f"after {arguments.pause} s",
                     "right after unmapping"):
            if when.startswith("after "):
                time.sleep(arguments.pause)
            first, second = touch(size, huge)
            print(f"{name} {when}: {first:.3f} s a GiB (first pass), {second:.3f} s a GiB (second pass)", flush=True)
    name = "4 KiB pages made resident first"
    for when in ("fresh", "right after unmapping", f"after {arguments.pause} s"):
        if when.startswith("after "):
            time.sleep(arguments.pause)
        try:
            advice, first, second = touch(size, False, resident_first=True)
        except OSError as error:  # a kernel before 5.14 does not know the advice
            print(f"{name}: not supported here ({error})", flush=True)
            return
        print(f"{name} {when}: {advice:.3f} s a GiB (made resident), {first:.3f} s a GiB (first pass), "
              f"{second:.3f} s a GiB (second pass)", flush=True)


if __name__ == "__main__":
    main()
