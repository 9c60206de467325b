#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""fwcheck.py - checks and figures of the firmware proof (docs/FIRMWARE.md).

  fwcheck.py doubles --nm NM [--float] ELF...  no double-precision helpers in the images
                                             (--float: no float helpers either)
  fwcheck.py qemu --qemu Q --out F --elf E -- <machine args>
                                             run the image, save its output, expect "END ok"
  fwcheck.py compare --target F --host EXE   per-frame confirmed counts equal,
                                             final states within tolerance (per
                                             run: CV lines F/T, IMM lines IF/IT)
  fwcheck.py size --size SIZE --nm NM --lib E --base E [--archive A]
                                             library .text/.data/.bss in a firmware
  fwcheck.py stack --build DIR --elf E --objdump OD --src DIR [--root F] [--lto]
                                             worst-case stack depth of F's call graph
                                             (--lto: from E's link, -flto builds)
  fwcheck.py insns --out F [--out F2 --imm]  instructions per frame from the icount runs
                                             (--imm: the IMM run's IC lines required)

Python 3 standard library only.  Methods: docs/FIRMWARE.md.
"""
import argparse
import os
import re
import struct
import subprocess
import sys

# ---------------------------------------------------------------- doubles

# Run-time ABI double helpers (__aeabi_dadd, __aeabi_f2d, __aeabi_i2d, ...) and
# their libgcc names (__adddf3, __extendsfdf2, __floatsidf, ...).
DOUBLE_HELPER = re.compile(
    r"^(__aeabi_(d[a-z0-9]+|f2d|i2d|ui2d|l2d|ul2d)|__[a-z]+df[0-9]?|__(fix|fixuns)df[a-z]i)$")
# Double-precision libm entry points (the float build must call the f versions).
DOUBLE_LIBM = {
    "sqrt", "exp", "log", "pow", "fabs", "sin", "cos", "tan", "atan", "atan2", "asin",
    "acos", "exp2", "log2", "log10", "log1p", "expm1", "floor", "ceil", "round", "fmod",
    "hypot", "cbrt", "erf", "erfc", "lgamma", "tgamma", "ldexp", "frexp", "modf",
    "sinh", "cosh", "tanh", "trunc", "fmin", "fmax", "fma", "scalbn",
}


def nm_symbols(nm, path):
    out = subprocess.run([nm, path], check=True, capture_output=True, text=True).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 2:
            syms.append((parts[-2], parts[-1]))
    return syms


# --float (the fixed-point images, docs/FIXED_POINT.md): single-precision
# helpers too (__aeabi_fadd, __aeabi_i2f, ...; libgcc's __addsf3, __fixsfsi,
# ...) and float libm (sqrtf, expf, ...).
FLOAT_HELPER = re.compile(
    r"^(__aeabi_(f[a-z0-9]+|u?i2f|u?l2f)|__[a-z]+sf[0-9]?|__(fix|fixuns)sf[a-z]i|__float[a-z]*sf)$")


def cmd_doubles(a):
    bad_total = 0
    what = "float or double helper(s)" if a.float else "double-precision helper(s)"
    for elf in a.elf:
        bad = sorted({name for kind, name in nm_symbols(a.nm, elf)
                      if DOUBLE_HELPER.match(name) or name in DOUBLE_LIBM
                      or (a.float and (FLOAT_HELPER.match(name)
                                       or (name.endswith("f") and name[:-1] in DOUBLE_LIBM)))})
        print(f"{os.path.basename(elf)}: {len(bad)} {what}"
              + (": " + " ".join(bad) if bad else ""))
        bad_total += len(bad)
    return 1 if bad_total else 0


# ---------------------------------------------------------------- qemu

QEMU_COMMON = ["-semihosting-config", "enable=on,target=native", "-nographic",
               "-monitor", "none", "-serial", "none", "-icount", "shift=0"]


def cmd_qemu(a):
    if not a.qemu or not os.path.exists(a.qemu):
        print("qemu-system-arm not found (Debian package qemu-system-arm)")
        return 1
    cmd = [a.qemu] + a.machine + QEMU_COMMON + ["-kernel", a.elf]
    print("$ " + " ".join(cmd))
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout,
                           stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        print(f"qemu: no exit within {a.timeout} s")
        return 1
    # Semihosting console output arrives on qemu's stderr.
    text = r.stdout + r.stderr
    with open(a.out, "w") as f:
        f.write(text)
    lines = text.splitlines()
    frames = sum(1 for l in lines if l.startswith("F "))
    imm_frames = sum(1 for l in lines if l.startswith("IF "))
    ok = r.returncode == 0 and "END ok" in lines
    print(f"qemu exit {r.returncode}; "
          + (f"{imm_frames} IMM frames; " if imm_frames else f"{frames} frames; ") +
          f"{'END ok' if ok else 'FAILED'}; output in {a.out}")
    if not ok:
        print("\n".join(lines[-20:]))
    return 0 if ok else 1


# ---------------------------------------------------------------- compare

# The runs of the scene, by line prefix: CV ("F", "C", "T" lines; mtt-fw)
# and IMM ("IF", "IC", "IT"; mtt-fw-imm, app.c's FW_IMM 1).
RUNS = {"": "CV", "I": "IMM"}


def parse_run(text):
    """{run prefix: (frames, tracks)} and the END reason."""
    runs, end = {}, None
    for line in text.splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "END":
            end = " ".join(f[1:])
            continue
        pre, kind = f[0][:-1], f[0][-1:]
        if pre not in RUNS or kind not in ("F", "T"):
            continue
        frames, tracks = runs.setdefault(pre, ({}, []))
        if kind == "F":
            frames[int(f[1])] = {"meas": int(f[3]), "live": int(f[5]), "conf": int(f[7])}
        else:
            if "qhex" in f:
                # fixed point: "qhex <position frac> <probability frac>" and the
                # 32-bit words of x, y, vx, vy (position format), existence (Q30)
                i = f.index("qhex")
                fp, fe = int(f[i + 1]), int(f[i + 2])
                w = [struct.unpack(">i", bytes.fromhex(x))[0] for x in f[i + 3:]]
                vals = [x / 2.0 ** (fp if k < 4 else fe) for k, x in enumerate(w)]
            else:
                h = f[f.index("hex") + 1:]
                vals = [struct.unpack(">f", bytes.fromhex(w))[0] for w in h]
            tracks.append({"id": int(f[1]), "conf": int(f[3]), "v": vals})
    return runs, end


def compare_run(tf, tt, hf, ht, rel, absol):
    """One run: the errors and the summary line."""
    errs = []
    if sorted(tf) != sorted(hf) or not tf:
        errs.append(f"frame sets differ: target {len(tf)} frames, host {len(hf)}")
    live_diff = 0
    for k in sorted(set(tf) & set(hf)):
        if tf[k]["meas"] != hf[k]["meas"]:
            errs.append(f"frame {k}: measurement count {tf[k]['meas']} != host {hf[k]['meas']}")
        if tf[k]["conf"] != hf[k]["conf"]:
            errs.append(f"frame {k}: confirmed {tf[k]['conf']} != host {hf[k]['conf']}")
        live_diff += tf[k]["live"] != hf[k]["live"]
    if len(tt) != len(ht):
        errs.append(f"final tracks: target {len(tt)} != host {len(ht)}")
    worst = 0.0
    names = ["x", "y", "vx", "vy", "existence"]
    for t, h in zip(tt, ht):
        if t["id"] != h["id"] or t["conf"] != h["conf"] or len(t["v"]) != len(h["v"]):
            errs.append(f"track id/conf/values {t['id']}/{t['conf']}/{len(t['v'])} != host "
                        f"{h['id']}/{h['conf']}/{len(h['v'])}")
        for i, (x, y) in enumerate(zip(t["v"], h["v"])):
            d = abs(x - y)
            tol = rel * max(abs(x), abs(y)) + absol
            worst = max(worst, d / tol)
            if not d <= tol:
                name = names[i] if i < len(names) else f"mu{i - len(names)}"
                errs.append(f"track {t['id']} {name}: target {x!r} host {y!r} (|d| {d:.3g} > {tol:.3g})")
    summary = (f"compared {len(tf)} frames (confirmed counts: "
               f"{'equal' if not any('confirmed' in e for e in errs) else 'DIFFER'}; "
               f"live counts differing in {live_diff} frames) and {len(tt)} final tracks; "
               f"largest |d| / tolerance {worst:.3g} (tolerance {rel:g} relative + {absol:g} absolute)")
    return errs, summary


def cmd_compare(a):
    rel, absol = a.rel, a.abs
    with open(a.target) as f:
        tp, tend = parse_run(f.read())
    r = subprocess.run([a.host], capture_output=True, text=True, timeout=120)
    hp, hend = parse_run(r.stdout)
    errs = []
    if r.returncode != 0 or hend != "ok":
        errs.append(f"host run failed (exit {r.returncode}, END {hend})")
    if tend != "ok":
        errs.append(f"target run did not end ok (END {tend})")
    if sorted(tp) != sorted(hp):
        errs.append("runs differ: target " + " ".join(RUNS[p] for p in sorted(tp))
                    + ", host " + " ".join(RUNS[p] for p in sorted(hp)))
    lines = []
    for pre in sorted(set(tp) | set(hp)):
        (tf, tt), (hf, ht) = tp.get(pre, ({}, [])), hp.get(pre, ({}, []))
        e, summary = compare_run(tf, tt, hf, ht, rel, absol)
        tag = f"{RUNS[pre]} run: " if pre else ""
        lines.append(tag + summary)
        errs += [tag + x for x in e]
    if not tp and not hp:
        errs.append("no frames in either run")
    for line in lines:
        print(line)
    for e in errs:
        print("  " + e)
    return 1 if errs else 0


# ---------------------------------------------------------------- size

def size_of(size, path):
    out = subprocess.run([size, "-A", path], check=True, capture_output=True, text=True).stdout
    sec = {}
    for line in out.splitlines():
        f = line.split()
        if len(f) >= 2 and f[0].startswith(".") and f[1].isdigit():
            sec[f[0]] = int(f[1])
    text = sum(v for k, v in sec.items() if k in (".isr_vector", ".text", ".ARM.exidx"))
    return {"text": text, "data": sec.get(".data", 0), "bss": sec.get(".bss", 0)}


def cmd_size(a):
    lib, base = size_of(a.size, a.lib), size_of(a.size, a.base)
    d = {k: lib[k] - base[k] for k in lib}
    trk = None
    out = subprocess.run([a.nm, "-S", a.base], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        f = line.split()
        if len(f) == 4 and f[3] == "trk":
            trk = int(f[1], 16)
    label = a.label or os.path.basename(os.path.dirname(os.path.dirname(a.lib)))
    print(f"{label}: library in a firmware (image difference): .text {d['text']} "
          f".data {d['data']} .bss {d['bss']} bytes; sizeof(mtt_tracker) {trk} bytes")
    if a.archive:
        out = subprocess.run([a.size, "-t", a.archive], check=True, capture_output=True,
                             text=True).stdout.splitlines()
        tot = out[-1].split()
        if int(tot[0]) == 0 and len(out) > 2:
            # -flto -fno-fat-lto-objects: the objects hold GCC's IR only
            print(f"{label}: libmtt.a holds link-time-optimisation IR (no per-object "
                  f".text): the image difference above is the figure")
        else:
            print(f"{label}: per-object sum of libmtt.a (before --gc-sections, no libm): "
                  f".text {tot[0]} .data {tot[1]} .bss {tot[2]} bytes")
    if a.text_limit and d["text"] > a.text_limit:
        print(f"{label}: note: .text {d['text']} > target {a.text_limit}")
    return 0


# ---------------------------------------------------------------- stack

CI_NODE = re.compile(r'^node: \{ title: "([^"]*)" label: "([^"]*)"')
CI_EDGE = re.compile(r'^edge: \{ sourcename: "([^"]*)" targetname: "([^"]*)"')


def strip_clone(name):
    return re.sub(r"\.(constprop|isra|part|cold|lto_priv)\.\d+", "", name)


def read_ci(build, lto_elf=None):
    """Frames and edges from the .ci files of the library's objects, or with
    link-time optimisation (lto_elf) from the link's own call graph, the
    <elf>.ltrans*.ltrans.ci files GCC writes beside the image (the code
    that is linked: the library's objects hold only GCC's IR then).  Also
    each node's source file (the label's second line)."""
    frames, edges, files, src = {}, {}, [], {}
    if lto_elf:
        d, base = os.path.split(os.path.abspath(lto_elf))
        files = [os.path.join(d, n) for n in os.listdir(d)
                 if n.startswith(base + ".ltrans") and n.endswith(".ltrans.ci")]
    else:
        for root, _, names in os.walk(os.path.join(build, "CMakeFiles", "mtt.dir")):
            files += [os.path.join(root, n) for n in names if n.endswith(".ci")]

    def node_id(title):
        # ltrans titles are "<tmp>.ltransN.o:<symbol>": the symbol (unique
        # in the link: GCC suffixes local clashes .lto_priv.N) is the id
        return title.split(":")[-1] if lto_elf else title

    for path in sorted(files):
        with open(path) as f:
            for line in f:
                m = CI_NODE.match(line)
                if m:
                    title, label = m.groups()
                    title = node_id(title)
                    where = label.split("\\n")
                    if len(where) > 1:
                        src[title] = where[1].split(":")[0]
                    s = re.search(r"\\n(\d+) bytes \(([^)]*)\)", label)
                    if s:
                        if "dynamic" in s.group(2) and "bounded" not in s.group(2):
                            raise SystemExit(f"unbounded dynamic stack in {title}")
                        frames[title] = int(s.group(1))
                    continue
                m = CI_EDGE.match(line)
                if m:
                    edges.setdefault(node_id(m.group(1)), set()).add(node_id(m.group(2)))
    if lto_elf:
        # the library's functions: those compiled from a .c file (not the
        # <built-in> helper nodes)
        frames = {t: v for t, v in frames.items() if src.get(t, "").endswith(".c")}
    return frames, edges, files, src


def address_taken(src_dir, names, src=None):
    """Library functions whose address is taken (the candidates of every
    indirect call inside the library): named in the source other than as
    a call or a declaration, i.e. not followed by '('."""
    plain = {}
    for t in names:
        plain.setdefault(strip_clone(t.split(":")[-1]), []).append(t)
    taken = set()
    paths = sorted(os.path.join(d, f) for d, _, fs in os.walk(src_dir) for f in fs)
    for path in paths:  # src/ has a directory per layer
        fn = os.path.basename(path)
        if not fn.endswith(".c"):
            continue
        with open(path) as f:
            text = f.read()
        text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
        text = re.sub(r"//[^\n]*", " ", text)
        for m in re.finditer(r"\b([A-Za-z_]\w*)\b(?!\s*\()", text):
            for t in plain.get(m.group(1), []):
                where = (src or {}).get(t) or t.split(":")[0]
                if t == m.group(1) or where.endswith("/" + fn):
                    taken.add(t)
    return taken


PUSH = re.compile(r"\b(push|stmdb\s+sp!,)\s*\{([^}]*)\}")
VPUSH = re.compile(r"\bvpush\s*\{([^}]*)\}")
SUBSP = re.compile(r"\bsub(?:s|\.w|w)?\s+sp,\s*(?:sp,\s*)?#(\d+)")
CALL = re.compile(r"\b(bl|blx|b\.w|b)\s+[0-9a-f]+\s+<([^>+]+)>")


def reg_count(regs):
    n = 0
    for part in regs.split(","):
        part = part.strip()
        m = re.match(r"([a-z]+)(\d+)-[a-z]+(\d+)", part)
        n += int(m.group(3)) - int(m.group(2)) + 1 if m else (1 if part else 0)
    return n


def objdump_functions(objdump, elf):
    """Per function symbol of the image: its stack frame from the prologue
    (push / vpush / sub sp) and the functions it calls or tail-calls."""
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], check=True,
                         capture_output=True, text=True).stdout
    funcs, cur = {}, None
    for line in out.splitlines():
        m = re.match(r"^[0-9a-f]+ <([^>]+)>:$", line)
        if m:
            cur = funcs.setdefault(m.group(1), {"frame": 0, "calls": set(), "seen_sub": False})
            continue
        if cur is None or ":" not in line:
            continue
        ins = line.split(":", 1)[1].strip()
        m = PUSH.search(ins)
        if m:
            cur["frame"] += 4 * reg_count(m.group(2))
        m = VPUSH.search(ins)
        if m:
            regs = m.group(1)
            cur["frame"] += (8 if regs.strip().startswith("d") else 4) * reg_count(regs)
        m = SUBSP.search(ins)
        if m:
            cur["frame"] += int(m.group(1))
        m = CALL.search(ins)
        if m:
            cur["calls"].add(m.group(2))
    for name, f in funcs.items():
        f["calls"].discard(name)  # branches inside the function
    return funcs


def cmd_stack(a):
    frames, edges, files, src = read_ci(a.build, a.elf if a.lto else None)
    if not files:
        print("no .ci files (build with -fcallgraph-info=su"
              + ("; with -flto on the link too" if a.lto else "") + ")")
        return 1
    lib_funcs = set(frames)
    taken = address_taken(a.src, lib_funcs, src)
    image = objdump_functions(a.objdump, a.elf) if a.elf else {}
    by_plain = {}
    for t in lib_funcs:
        by_plain.setdefault(strip_clone(t.split(":")[-1]), []).append(t)

    def callees(node):
        out = set()
        for t in edges.get(node, ()):
            if t == "__indirect_call":
                out.add("__indirect_call")
            elif t in lib_funcs:
                out.add(t)
            elif t in by_plain:  # a global declared in another file
                out.update(by_plain[t])
            else:
                out.add("ext:" + t)
        if node in lib_funcs:
            # library calls the compiler emitted (soft-float, division, mem*):
            # from the linked image, under the function's symbol name.
            sym = node.split(":")[-1]
            for c in image.get(sym, {}).get("calls", ()):
                if strip_clone(c) in by_plain:
                    out.update(by_plain[strip_clone(c)])
                else:
                    out.add("ext:" + c)
        elif node.startswith("ext:"):
            for c in image.get(node[4:], {}).get("calls", ()):
                out.add(("ext:" + c) if strip_clone(c) not in by_plain else by_plain[strip_clone(c)][0])
        elif node == "__indirect_call":
            out.update(taken)
        return out

    def frame(node):
        if node in frames:
            return frames[node]
        if node.startswith("ext:"):
            return image.get(node[4:], {}).get("frame", 0)
        return 0

    memo, missing = {}, set()

    def worst(node, path):
        if node in path:
            raise SystemExit("recursion: " + " -> ".join(path + [node]))
        if node in memo:
            return memo[node]
        if node.startswith("ext:") and node[4:] not in image:
            missing.add(node[4:])
        best, best_path = 0, []
        for c in sorted(callees(node)):
            d, p = worst(c, path + [node])
            if d > best:
                best, best_path = d, p
        memo[node] = (frame(node) + best, [node] + best_path)
        return memo[node]

    root = a.root
    if root not in lib_funcs:
        print(f"{root}: not found in the .ci files")
        return 1
    total, path = worst(root, [])
    lib_only = sum(frame(n) for n in path if n in lib_funcs)
    label = a.label or os.path.basename(os.path.normpath(a.build))
    print(f"{label}: worst-case stack of {root}: {total} bytes "
          f"({lib_only} in library frames, {total - lib_only} in libm/libgcc/libc frames)")
    print(f"{label}:   deepest path: " + " -> ".join(
        f"{n.split(':')[-1].replace('ext:', '')}({frame(n)})" for n in path))
    print(f"{label}:   indirect-call candidates (address-taken library functions): "
          + " ".join(sorted(t.split(":")[-1] for t in taken)))
    if missing:
        print(f"{label}:   not in the image (frame counted 0): " + " ".join(sorted(missing)))
    if a.limit and total > a.limit:
        print(f"{label}:   note: {total} > target {a.limit}")
    return 0


# ---------------------------------------------------------------- insns

STAGE_NAMES = ["validate", "predict", "gate", "lm_clutter", "associate", "update",
               "initiate", "merge", "manage"]


def cmd_insns(a):
    rows, cals = {"C": [], "IC": []}, []
    for path in a.out:
        with open(path) as f:
            for line in f:
                w = line.split()
                if w and w[0] in rows:
                    rows[w[0]].append((int(w[3]), int(w[1]), [int(x) for x in w[5:]]))
                elif w and w[0] == "K":
                    cals.append((int(w[2]), int(w[4])))
    if not rows["C"]:
        print("no C lines (tick counts) in " + " ".join(a.out))
        return 1
    if a.imm and not rows["IC"]:
        print("no IC lines (tick counts of the IMM run) in " + " ".join(a.out))
        return 1
    ratio = a.ns_per_tick
    for cal in cals:
        print(f"calibration: a loop of {cal[0]} instructions measured {cal[1]} ticks "
              f"= {cal[0] / cal[1]:.2f} instructions per tick (expected {ratio})")
    label = a.label or "mtt_tracker_step"
    busiest = {}
    for kind, tag in (("C", ""), ("IC", "IMM ")):
        if not rows[kind]:
            continue
        ticks, k, stages = max(rows[kind])
        busiest[kind] = ticks
        mean = sum(r[0] for r in rows[kind]) / len(rows[kind])
        print(f"{label}: {tag}busiest frame {k}: {ticks} ticks = {ticks * ratio} instructions "
              f"(+-{ratio}); mean over {len(rows[kind])} frames {mean * ratio:.0f} instructions")
        print(f"{label}:   per stage (instructions): " + ", ".join(
            f"{n} {s * ratio}" for n, s in zip(STAGE_NAMES, stages)))
    if "IC" in busiest:
        print(f"{label}: busiest IMM frame / busiest CV frame: {busiest['IC'] / busiest['C']:.2f}")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("doubles")
    p.add_argument("--nm", required=True)
    p.add_argument("--float", action="store_true",
                   help="single-precision helpers and float libm too (fixed-point images)")
    p.add_argument("elf", nargs="+")
    p = sub.add_parser("qemu")
    p.add_argument("--qemu", default="")
    p.add_argument("--out", required=True)
    p.add_argument("--elf", required=True)
    p.add_argument("--timeout", type=int, default=240)
    p.add_argument("machine", nargs="*")
    p = sub.add_parser("compare")
    p.add_argument("--target", required=True)
    p.add_argument("--host", required=True)
    p.add_argument("--rel", type=float, default=1e-3)
    p.add_argument("--abs", type=float, default=1e-3)
    p = sub.add_parser("size")
    p.add_argument("--size", required=True)
    p.add_argument("--nm", required=True)
    p.add_argument("--lib", required=True)
    p.add_argument("--base", required=True)
    p.add_argument("--archive")
    p.add_argument("--label")
    p.add_argument("--text-limit", type=int, default=0)
    p = sub.add_parser("stack")
    p.add_argument("--build", required=True)
    p.add_argument("--src", required=True)
    p.add_argument("--elf")
    p.add_argument("--objdump", default="arm-none-eabi-objdump")
    p.add_argument("--root", default="mtt_tracker_step")
    p.add_argument("--lto", action="store_true",
                   help="link-time optimisation: the call graph of --elf's link (its .ltrans .ci files)")
    p.add_argument("--label")
    p.add_argument("--limit", type=int, default=0)
    p = sub.add_parser("insns")
    p.add_argument("--out", required=True, action="append")
    p.add_argument("--ns-per-tick", type=int, default=40)
    p.add_argument("--label")
    p.add_argument("--imm", action="store_true",
                   help="the build has the IMM: the IMM run's IC lines are required")
    a = ap.parse_args()
    return {"doubles": cmd_doubles, "qemu": cmd_qemu, "compare": cmd_compare,
            "size": cmd_size, "stack": cmd_stack, "insns": cmd_insns}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())
