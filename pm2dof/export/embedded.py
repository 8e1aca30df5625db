# make embedded: the exported step cross-compiled for Cortex-M4F and M7, run under QEMU.
"""``pm2dof export [MODEL] --embedded --out DIR`` (what ``make embedded`` runs).

For double and single precision: export the model (single precision: build it with CMake and
run its ctest on the host, the checks of docs/deploying.md), build ``embedded/replay.c`` for
the host and for a Cortex-M4F (QEMU ``mps2-an386``) and a Cortex-M7 (``mps2-an500``) with
arm-none-eabi-gcc and newlib, run the three, and report:

* whether the torques along the move equal the host build's, bit for bit, else the largest
  difference;
* the code and data size of the controller (the ``<name>_`` symbols kept in the linked ELF)
  and of the whole test program (arm-none-eabi-size);
* the deepest stack a step used (the stack painted before the steps, read after) and the
  largest frame of the step's own functions (-fstack-usage);
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

from .project import export_project

__all__ = ["run_embedded", "format_results", "TARGETS", "CPI", "CLOCK_HZ", "BOUND_NM", "TOOLS",
           "INSTALL"]

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
TOOLS = ("arm-none-eabi-gcc", "arm-none-eabi-size", "arm-none-eabi-nm", "qemu-system-arm")
INSTALL = "apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm"


def _torques(path, single):
    """{law: [(status, (bits, ...)), ...]} and the S/K lines of a replay output."""
    tau, stats, stack, host_ns = {}, {}, {}, {}
    for line in Path(path).read_text().splitlines():
        f = line.split()
        if f[:1] == ["T"]:
            tau.setdefault(f[1], []).append((int(f[3]), tuple(f[4:])))
        elif f[:1] == ["S"]:
            stats[f[1]] = tuple(int(x) for x in f[2:5])
        elif f[:1] == ["K"]:
            stack[f[1]] = int(f[2])
        elif f[:1] == ["H"]:
            host_ns[f[1]] = float(f[2])
    return tau, stats, stack, host_ns


def _value(bits, single):
    return struct.unpack(">f" if single else ">d", bytes.fromhex(bits))[0]


def _compare(host, target, single):
    """(bit-identical samples, samples, largest |difference| N m, statuses equal)."""
    same = total = 0
    worst = 0.0
    statuses = True
    for law, rows in host.items():
        for (s0, b0), (s1, b1) in zip(rows, target.get(law, [])):
            total += 1
            same += b0 == b1
            statuses &= s0 == s1
            for x, y in zip(b0, b1):
                worst = max(worst, abs(_value(x, single) - _value(y, single)))
        statuses &= len(rows) == len(target.get(law, []))
    return same, total, worst, statuses


def _symbol_sizes(elf, name):
    """Bytes of code and of read-only/initialised data of the ``<name>_`` symbols in ``elf``."""
    out = subprocess.run(["arm-none-eabi-nm", "--print-size", str(elf)], capture_output=True,
                         text=True, check=True).stdout
    code = data = 0
    for line in out.splitlines():
        f = line.split()
        if len(f) == 4 and f[3].startswith(f"{name}_"):
            size = int(f[1], 16)
            if f[2] in "tT":
                code += size
            else:
                data += size
    return code, data


def _elf_size(elf):
    out = subprocess.run(["arm-none-eabi-size", str(elf)], capture_output=True, text=True,
                         check=True).stdout.splitlines()[1].split()
    return {"text": int(out[0]), "data": int(out[1]), "bss": int(out[2])}


def _step_chain(c_text, name, gen):
    """The functions a step runs through in the generated code: ``<name>_<gen>`` and the
    ``casadi_f<k>`` it calls, recursively (their symbols are ``<name>_f<k>``)."""
    m = re.search(rf"int {name}_{gen}\([^)]*\)\s*{{\s*return casadi_(f\d+)\(", c_text)
    chain, todo = [f"{name}_{gen}"], [m.group(1)] if m else []
    while todo:
        f = todo.pop()
        if f"{name}_{f}" in chain:
            continue
        chain.append(f"{name}_{f}")
        body = re.search(rf"static int casadi_{f}\(.*?\n}}\n", c_text, re.S)
        todo += re.findall(r"casadi_(f\d+)\(", body.group(0)[20:]) if body else []
    return chain


def _static_stack(build, name, law, c_text, gen):
    """Bytes of stack of a step's call chain by -fstack-usage: the API's step, its core, the
    generated step and the functions it calls (the math library's frames are not in it)."""
    frames = {}
    for su in Path(build).glob("*.su"):
        for line in su.read_text().splitlines():
            parts = line.split("\t")
            if len(parts) >= 2:
                fn = parts[0].split(":")[-1].split(".")[0]
                frames[fn] = max(frames.get(fn, 0), int(parts[1]))
    chain = [f"{name}_pm2dof_{law}_step", "core_step", *_step_chain(c_text, name, gen)]
    return sum(frames.get(f, 0) for f in chain)


def run_embedded(out, model="shang2010", jobs=2, progress=print):
    """Build and run everything (module doc); returns the results as a dict."""
    missing = [t for t in TOOLS if shutil.which(t) is None]
    if missing:
        raise SystemExit(f"make embedded needs {', '.join(missing)}: {INSTALL} (Debian)")
    out = Path(out)
    results = {"model": model, "icount_shift": ICOUNT_SHIFT, "cpi": CPI, "clock_hz": CLOCK_HZ,
               "budget_s": BUDGET_S, "runs": {}}
    for precision in ("double", "single"):
        single = precision == "single"
        proj = export_project(model, out / precision, precision=precision, force=True)
        record = json.loads((proj / "pm2dof_export.json").read_text())
        name = record["model"]
        c_text = (proj / "src" / f"{name}.c").read_text()
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
            tau, stats, stack, _ = _torques(build / target / "replay.txt", single)
            same, total, worst, statuses = _compare(host, tau, single)
            code, data = _symbol_sizes(build / target / "replay.elf", name)
            steps = {}
            for law, (lo, hi, tot) in stats.items():
                n = len(tau[law])
                per_tick = 2 ** ICOUNT_SHIFT * SYSTICK_HZ / 1e9    # ticks per instruction
                steps[law] = {"min": lo / per_tick, "max": hi / per_tick,
                              "mean": tot / per_tick / n}
            results["runs"][f"{target}-{precision}"] = {
                "target": TARGETS[target], "precision": precision,
                "bit_identical": same, "samples": total, "max_abs_diff_Nm": worst,
                "statuses_equal": statuses, "controller_code_bytes": code,
                "controller_data_bytes": data, "elf": _elf_size(build / target / "replay.elf"),
                "stack_painted_bytes": max(stack.values()) if stack else None,
                "stack_static_bytes_na": _static_stack(build / target, name, "na", c_text,
                                                       "na_step"),
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
                 f"{r['bit_identical']}/{r['samples']} identical, max {r['max_abs_diff_Nm']:.2g}"
                 f" N m")
        lines.append(
            f"| {r['target']} | {r['precision']} | {agree} | "
            f"{r['controller_code_bytes'] / 1024:.1f} KiB | {r['stack_painted_bytes']} B / "
            f"{r['stack_static_bytes_na']} B | {na['mean']:.0f}, {na['max']:.0f} | "
            f"{c_lo:.0f}-{c_hi:.0f} at "
            f"{clock / 1e6:.0f} MHz | {c_lo / clock * 1e6:.0f}-{c_hi / clock * 1e6:.0f} us "
            f"({c_hi / clock / BUDGET_S * 100:.1f} % of the budget at most) |")
    return "\n".join(lines)
