# make embedded: the exported step cross-compiled for Cortex-M4F and M7, run under QEMU.
"""``pm2dof export [MODEL] --embedded --out DIR`` (what ``make embedded [MODEL=...]``
runs), for any model whose generated code is current.

For double and single precision (single only where the export allows it): export the model
(single precision: build it with CMake and run its ctest on the host, the checks of
docs/deploying.md), build ``embedded/replay.c`` for the host and for a Cortex-M4F (QEMU
``mps2-an386``) and a Cortex-M7 (``mps2-an500``) with arm-none-eabi-gcc and newlib, run the
three, and report:

* whether the torques along the move equal the host build's, bit for bit, else the largest
  difference;
* the code and data size of the controller (the library's symbols kept in the linked ELF)
  and of the whole test program (arm-none-eabi-size);
* the deepest stack a step used (the stack painted before the steps, read after) and the
  worst-case stack of each step's call chain from GCC's call graph (-fcallgraph-info,
  :mod:`.stack`; the math library's frames not counted);
* the instructions per step: QEMU with ``-icount`` advances its virtual clock by 2^shift ns
  per instruction, and SysTick counts that clock, so the ticks count instructions -- not
  cycles. The cycle estimate is a range of cycles per instruction (CPI) at a stated clock.
"""
import json
import re
import shutil
import struct
import subprocess
from pathlib import Path

from ..core.model import load_model
from ..core.task import effort_unit
from . import names, stack
from .project import ExportError, export_project

__all__ = ["run_embedded", "format_results", "format_stacks", "TARGETS", "CPI", "CLOCK_HZ",
           "BOUND_NM", "TOOLS", "INSTALL"]

TARGETS = {"m4f": "Cortex-M4F (mps2-an386)", "m7": "Cortex-M7 (mps2-an500)"}
ICOUNT_SHIFT = 6              # embedded/Makefile: one instruction = 2^6 ns of virtual time
SYSTICK_HZ = 25e6             # the MPS2 boards' SysTick clock in QEMU
#: cycles per instruction assumed for the estimate (low, high): the M4F issues one
#: instruction per cycle at best, loads and branches take 2-3, VDIV/VSQRT 14, flash wait
#: states add more; the M7 dual-issues (below 1) but stalls on cache misses
CPI = {"m4f": (1.0, 2.0), "m7": (0.7, 1.5)}
#: clocks of common parts: STM32F407 (M4F) 168 MHz, STM32F767 (M7) 216 MHz
CLOCK_HZ = {"m4f": 168e6, "m7": 216e6}
BUDGET_S = 0.002
#: largest |torque difference| from the host build along the move, N m. IEEE arithmetic is the
#: same on both sides (no FMA: -ffp-contract=off; the M4F emulates double exactly in libgcc);
#: the math library is not: newlib's sin/cos/atan2 (fdlibm) differ from glibc's by an ulp now
#: and then, and on the M4F (no double FPU) newlib's sinf/cosf are fdlibm's float routines, not
#: the correctly rounded ones of glibc (and of newlib on the M7). An ulp of xe becomes ulp/T of
#: velocity estimate and K_d ulp/T of force (double: 5e-12 N per ulp at 0.5 m; float: 3e-3 N),
#: and the state (v, theta_hat) carries it on: bounds of a few hundred ulps' worth
BOUND_NM = {"double": 1e-9, "single": 0.05}
#: the same for a linear actuator's force, N: the same task force without the 0.244 m lever of
#: the paper's proximal link (as the exported ctest's 0.2 N in single precision)
BOUND_N = {"double": 4e-9, "single": 0.2}
TOOLS = ("arm-none-eabi-gcc", "arm-none-eabi-size", "arm-none-eabi-nm", "arm-none-eabi-readelf",
         "qemu-system-arm")
INSTALL = "apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm"


def _torques(path, single):
    """{law: [(status, (bits, ...)), ...]} and the S/K lines of a replay output."""
    tau, stats, painted, host_ns = {}, {}, {}, {}
    for line in Path(path).read_text().splitlines():
        f = line.split()
        if f[:1] == ["T"]:
            tau.setdefault(f[1], []).append((int(f[3]), tuple(f[4:])))
        elif f[:1] == ["S"]:
            stats[f[1]] = tuple(int(x) for x in f[2:5])
        elif f[:1] == ["K"]:
            painted[f[1]] = int(f[2])
        elif f[:1] == ["H"]:
            host_ns[f[1]] = float(f[2])
    return tau, stats, painted, host_ns


def _value(bits, single):
    return struct.unpack(">f" if single else ">d", bytes.fromhex(bits))[0]


def _flip_allowances(reference):
    """{law: per-sample allowance} of a single-precision export's reference header (the
    ``ref_replay_flip`` rows, laws in the header's order): where an actuator is at rest, float
    may flip its Coulomb sign (pm2dof.export.reference.coulomb_flip_bounds); {} in double."""
    text = Path(reference).read_text()
    m = re.search(r"ref_replay_flip\[[^=]*= \{(.*?)\};", text, re.S)
    if m is None:
        return {}
    laws = re.search(r"/\* in the order ([\w, ]+) \*/", text).group(1).split(", ")
    rows = re.findall(r"\{([^{}]*)\}", m.group(1))
    return {law: [float(v) for v in row.split(",")] for law, row in zip(laws, rows)}


def _compare(host, target, single, bound, allow):
    """(bit-identical samples, samples, largest |difference|, statuses equal, efforts within
    a flipped Coulomb sign): a difference beyond ``bound`` but within ``bound`` plus the
    sample's allowance (``allow``, :func:`_flip_allowances`) is counted apart, as the
    exported ctest does."""
    same = total = flips = 0
    worst = 0.0
    statuses = True
    for law, rows in host.items():
        for k, ((s0, b0), (s1, b1)) in enumerate(zip(rows, target.get(law, []))):
            total += 1
            same += b0 == b1
            statuses &= s0 == s1
            for x, y in zip(b0, b1):
                d = abs(_value(x, single) - _value(y, single))
                if bound < d <= bound + allow.get(law, [0.0] * (k + 1))[k]:
                    flips += 1
                else:
                    worst = max(worst, d)
        statuses &= len(rows) == len(target.get(law, []))
    return same, total, worst, statuses, flips


def _agreement(same, total, worst, statuses, flips, unit):
    """A target's comparison with the host (:func:`_compare`) as fields of its run.

    ``max_abs_diff`` is the largest |effort difference| in ``units["max_abs_diff"]`` (N m for
    revolute actuators, N for linear ones: :func:`pm2dof.core.task.effort_unit`). The same
    number stays under its former name ``max_abs_diff_Nm`` for readers of older results; it is
    in N for a linear actuator despite that name, and ``units`` says so for both keys."""
    return {"bit_identical": same, "samples": total, "max_abs_diff": worst,
            "max_abs_diff_Nm": worst, "units": {"max_abs_diff": unit, "max_abs_diff_Nm": unit},
            "coulomb_flips": flips, "statuses_equal": statuses}


def _symbol_sizes(elf, obj):
    """Bytes of code and of read-only/initialised data that the library's object ``obj``
    (one translation unit) contributes to the linked ``elf``: its global symbols, by name,
    and its local ones, those listed after its FILE symbol (readelf's symbol table)."""
    own = set(subprocess.run(["arm-none-eabi-nm", "-g", "--defined-only", "--format=just-symbols",
                              str(obj)], capture_output=True, text=True,
                             check=True).stdout.split())
    table = subprocess.run(["arm-none-eabi-readelf", "-sW", str(elf)], capture_output=True,
                           text=True, check=True).stdout
    code = data = 0
    current = None
    for line in table.splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(":"):
            continue
        kind, bind, sym = f[3], f[4], f[7]
        if kind == "FILE":
            current = sym
            continue
        mine = (sym in own) if bind == "GLOBAL" else current == Path(obj).with_suffix(".c").name
        if mine and kind in ("FUNC", "OBJECT") and int(f[2]) > 0:
            if kind == "FUNC":
                code += int(f[2])
            else:
                data += int(f[2])
    return code, data


def _elf_size(elf):
    out = subprocess.run(["arm-none-eabi-size", str(elf)], capture_output=True, text=True,
                         check=True).stdout.splitlines()[1].split()
    return {"text": int(out[0]), "data": int(out[1]), "bss": int(out[2])}


def _static_stacks(build, proj, name):
    """{law: worst-case stack of its step, bytes} from the call graph GCC wrote beside the
    library's object (-fcallgraph-info=su, embedded/Makefile), and whether each is bounded."""
    header = (proj / "include" / f"{name}_pm2dof.h").read_text()
    link = names.link_names(header, name)
    graph = stack.read_callgraph([Path(build) / f"{name}_pm2dof.ci"])
    out = {}
    for f in names.api_functions(header, name):
        m = re.fullmatch(rf"{name}_pm2dof_(\w+)_step", f)
        if m:
            s = stack.worst_stack(graph, link.get(f, f))
            out[m.group(1)] = {"bytes": s.bytes, "bounded": s.bounded, "chain": list(s.chain),
                               "not_counted": list(s.external)}
    return out


def run_embedded(out, model="shang2010", jobs=2, progress=print):
    """Build and run everything (module doc); returns the results as a dict."""
    missing = [t for t in TOOLS if shutil.which(t) is None]
    if missing:
        raise SystemExit(f"make embedded needs {', '.join(missing)}: {INSTALL} (Debian)")
    out = Path(out)
    results = {"model": model, "icount_shift": ICOUNT_SHIFT, "cpi": CPI, "clock_hz": CLOCK_HZ,
               "budget_s": BUDGET_S, "runs": {}, "refused": {}}
    for precision in ("double", "single"):
        single = precision == "single"
        try:
            proj = export_project(model, out / precision, precision=precision, force=True,
                                  measure_stack=False)
        except ExportError as exc:          # single precision where float is not enough
            progress(f"{precision}: not exported ({exc})")
            results["refused"][precision] = str(exc)
            continue
        record = json.loads((proj / "pm2dof_export.json").read_text())
        name = record["model"]
        results["model"] = name
        m = load_model(model)
        linear = "prismatic" in {leg.actuator for leg in m.spec.legs}
        results["effort_unit"] = effort_unit(m)
        results["bound"] = (BOUND_N if linear else BOUND_NM)
        progress(f"{precision}: building and running the replay for the host, M4F and M7 "
                 f"(QEMU) in {proj / 'embedded'}")
        subprocess.run(["make", "-s", "-j", str(jobs), "-C", str(proj / "embedded"), "run"],
                       check=True, stdout=subprocess.DEVNULL)
        if single and shutil.which("cmake"):    # double's ctest runs in tests/export
            progress(f"single: the exported project's ctest on the host (CMake, {proj})")
            for cmd in (["cmake", "-S", proj, "-B", proj / "build",
                         f"-D{name.upper()}_PM2DOF_WERROR=ON"],
                        ["cmake", "--build", proj / "build", "-j", str(jobs)],
                        ["ctest", "--test-dir", proj / "build", "--output-on-failure"]):
                subprocess.run([str(c) for c in cmd], check=True, stdout=subprocess.DEVNULL)
        build = proj / "embedded" / "build"
        host, _, _, host_ns = _torques(build / "host" / "replay.txt", single)
        results["runs"][f"host-{precision}"] = {"target": "host (x86-64, cc -O2)",
                                                "precision": precision, "step_ns": host_ns}
        for target in TARGETS:
            tau, stats, painted, _ = _torques(build / target / "replay.txt", single)
            same, total, worst, statuses, flips = _compare(
                host, tau, single, results["bound"][precision],
                _flip_allowances(proj / "tests" / f"{name}_reference.h"))
            code, data = _symbol_sizes(build / target / "replay.elf",
                                       build / target / f"{name}_pm2dof.o")
            chains = _static_stacks(build / target, proj, name)
            steps = {}
            for law, (lo, hi, tot) in stats.items():
                n = len(tau[law])
                per_tick = 2 ** ICOUNT_SHIFT * SYSTICK_HZ / 1e9    # ticks per instruction
                steps[law] = {"min": lo / per_tick, "max": hi / per_tick,
                              "mean": tot / per_tick / n}
            results["runs"][f"{target}-{precision}"] = {
                "target": TARGETS[target], "precision": precision,
                **_agreement(same, total, worst, statuses, flips, results["effort_unit"]),
                "controller_code_bytes": code,
                "controller_data_bytes": data, "elf": _elf_size(build / target / "replay.elf"),
                "stack_painted_bytes": max(painted.values()) if painted else None,
                "stack_static_bytes": {law: c["bytes"] for law, c in chains.items()},
                "stack_static_chains": chains,
                "instructions_per_step": steps}
    return results


def format_results(res):
    """The results as the table of docs/deploying.md."""
    lines = ["| target | precision | torques = host | controller code | stack (painted / "
             "static) | NA step: instructions (mean, max) | cycles at the clock | time vs 2 ms |",
             "|---|---|---|---|---|---|---|---|"]
    for key, r in res["runs"].items():
        target = key.split("-")[0]
        if target == "host":
            ns = r["step_ns"].get("na") or next(iter(r["step_ns"].values()))
            lines.append(f"| {r['target']} | {r['precision']} | (the reference) | | | | | "
                         f"{ns:.0f} ns measured (mean over replays) |")
            continue
        na = r["instructions_per_step"].get("na") or next(iter(r["instructions_per_step"]
                                                                .values()))
        lo, hi = CPI[target]
        c_lo, c_hi = na["max"] * lo, na["max"] * hi
        clock = CLOCK_HZ[target]
        agree = ("bit-identical" if r["bit_identical"] == r["samples"] else
                 f"{r['bit_identical']}/{r['samples']} identical, max {r['max_abs_diff']:.2g}"
                 f" {r['units']['max_abs_diff']}")
        if r.get("coulomb_flips"):
            agree += f" ({r['coulomb_flips']} efforts within a flipped Coulomb sign)"
        lines.append(
            f"| {r['target']} | {r['precision']} | {agree} | "
            f"{r['controller_code_bytes'] / 1024:.1f} KiB | {r['stack_painted_bytes']} B / "
            f"{max(r['stack_static_bytes'].values())} B | {na['mean']:.0f}, {na['max']:.0f} | "
            f"{c_lo:.0f}-{c_hi:.0f} at "
            f"{clock / 1e6:.0f} MHz | {c_lo / clock * 1e6:.0f}-{c_hi / clock * 1e6:.0f} us "
            f"({c_hi / clock / BUDGET_S * 100:.1f} % of the budget at most) |")
    return "\n".join(lines)


def format_stacks(res):
    """Each step's worst-case stack from the call graph, per target and precision."""
    lines = ["| target | precision | " + " | ".join(
        f"{law.upper()} step" for law in next((r["stack_static_bytes"] for r in
                                               res["runs"].values() if "stack_static_bytes" in r),
                                              {})) + " |"]
    lines.append("|---" * (lines[0].count("|") - 1) + "|")
    for r in res["runs"].values():
        if "stack_static_bytes" in r:
            lines.append(f"| {r['target']} | {r['precision']} | " + " | ".join(
                f"{b:,} B" for b in r["stack_static_bytes"].values()) + " |")
    return ("Worst-case stack of each step, bytes (GCC's call graph, -fcallgraph-info; the math "
            "library's and libgcc's frames not counted):\n" + "\n".join(lines))

