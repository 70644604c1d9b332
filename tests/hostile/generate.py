#!/usr/bin/env python3
"""Generates the hostile corpus of issue 10: tests/hostile/cases/*.yaml and
tests/hostile/expected.tsv, which tests/it/hostile.rs runs (no Python needed to
run the tests; this script only regenerates the committed files).

Every case says what it tests and how `vbi check` must answer:

  rejected  exit 2, a diagnostic at the marked line:column with the message
            (unmarked: at some location)
  budget    exit 2, refused by a resource limit (`limits.KEY` in the message),
            at the marked place
  accepted  exit 0

and, whatever the outcome, within the test's time and memory caps, without a
panic. The place of the expected diagnostic is marked in a case's text with
`@@` (removed from the file written); the columns count characters.

Run from the repository root:  python3 tests/hostile/generate.py
"""

import os
import shutil

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "cases")

BEAM = """bridge:
  type: beam
  spans: [25.0]
  bending_stiffness: 8.323e9
  mass_per_length: 2303.0
"""

OSC = """  - type: oscillator
    sprung_mass: 5750.0
    stiffness: 1.595e6
    speed: 27.7
"""

PLATE = """bridge:
  type: plate
  spans: [24.0, 30.0, 24.0]
  width: 13.0
  thickness: 0.2
  mass_per_area: 500.0
  rigidity: {type: isotropic, youngs_modulus: 3.0e10}
"""


def scene(name="hostile", bridge=BEAM, vehicles=OSC, extra=""):
    return f"name: {name}\n{bridge}vehicles:\n{vehicles}{extra}"


cases = []


def case(file, outcome, what, text, message=""):
    """One corpus file. `text` may be str or bytes; `@@` marks the place."""
    cases.append((file, outcome, what, text, message))


# --- accepted: ordinary and odd-but-valid files -------------------------------
case("ok-plain", "accepted", "the base scene every other case mutates", scene())
case("ok-bom", "accepted", "a UTF-8 byte order mark (Windows editors) is accepted",
     "\ufeff" + scene())
case("ok-crlf", "accepted", "CRLF line breaks are accepted", scene().replace("\n", "\r\n"))
case("ok-cr", "accepted", "lone CR line breaks are accepted", scene().replace("\n", "\r"))
case("ok-name-dotdot-path", "accepted",
     "a name with `../..` is accepted (the output folder is sanitised, not the title)",
     scene(name="../../escape"))
case("ok-name-absolute", "accepted", "an absolute path as name is accepted as a title",
     scene(name="/tmp/vbi-escape"))
case("ok-name-dotdot", "accepted", "`..` as a name is accepted as a title", scene(name="'..'"))
case("ok-name-unicode", "accepted", "a Unicode name", scene(name="pont de l'Île"))
case("size-limits-self-raised", "budget",
     "a file raising its own wheel limit for 600 axles is refused unless the command line "
     "allows it (`--trust-limits`; tests/it/hostile.rs runs it so) (issue 23; one record, so "
     "that the trusted run stays small: the default records would write 400 MB)",
     scene(vehicles="  @@- type: moving_force\n    loads: [" + ", ".join(["1e4"] * 600)
           + "]\n    axle_spacings: [" + ", ".join(["0.1"] * 599) + "]\n    speed: 20.0\n",
           extra="record: [{name: midspan, quantity: bridge_displacement, x: 12.5}]\n"
                 "limits: {wheels: 1000, modes: 1.0e15, eigen_work: 1.0e15}\n"),
     "--trust-limits")
case("size-default-records", "budget",
     "a file lowering its records limit (lowering always applies): 450 axles give 451 "
     "default records",
     scene(vehicles="  @@- type: moving_force\n    loads: [" + ", ".join(["1e4"] * 450)
           + "]\n    axle_spacings: [" + ", ".join(["0.1"] * 449) + "]\n    speed: 20.0\n",
           extra="limits: {records: 400}\n"), "limits.records")
case("size-axles-600", "budget", "the same 600 axles without the raised limit",
     scene(vehicles="  @@- type: moving_force\n    loads: [" + ", ".join(["1e4"] * 600)
           + "]\n    axle_spacings: [" + ", ".join(["0.1"] * 599) + "]\n    speed: 20.0\n"),
     "limits.wheels")
case("ok-anchors", "accepted", "anchors and aliases within bounds",
     "name: a\nbridge: &b\n  type: beam\n  spans: [25.0]\n  bending_stiffness: 8.323e9\n"
     "  mass_per_length: 2303.0\nvehicles:\n" + OSC)
case("ok-comments-everywhere", "accepted", "comments on every line",
     "\n".join(l + "  # c" for l in scene().splitlines()) + "\n")
case("ok-quoted-keys", "accepted", "quoted keys", scene().replace("bridge:", "'bridge':"))
case("ok-flow-style", "accepted", "the whole scene in flow style",
     "{name: f, bridge: {type: beam, spans: [25.0], bending_stiffness: 8.323e9, "
     "mass_per_length: 2303.0}, vehicles: [{type: oscillator, sprung_mass: 5750.0, "
     "stiffness: 1.595e6, speed: 27.7}]}\n")

# --- syntax: the YAML itself ---------------------------------------------------
case("syntax-tab-indent", "rejected", "a tab in the indentation is blamed on its line",
     scene(bridge=BEAM.replace("  spans", "@@\tspans")), "tabs")
case("syntax-missing-colon", "rejected", "a key without a colon is blamed on its line",
     scene(bridge=BEAM.replace("  spans: [25.0]", "  @@spans [25.0]")), "no `:`")
case("syntax-no-space-after-colon", "rejected", "`key:value` is blamed on its line",
     scene(bridge=BEAM.replace("  spans: [25.0]", "  @@spans:[25.0]")), "space after it")
case("syntax-custom-tag", "rejected", "a custom tag is blamed on the tag",
     scene(bridge=BEAM.replace("spans: [25.0]", "spans: @@!foo [25.0]")), "tags are not supported")
case("syntax-core-tag", "rejected", "a core tag `!!str` is blamed on the tag",
     scene(name="@@!!str x"), "tags are not supported")
case("syntax-nul-byte", "rejected", "a NUL byte is refused where it is, not read as end of file",
     scene().replace("  mass_per_length: 2303.0", "  mass_per_length: 2303.0@@\0"),
     "U+0000")
case("syntax-bell", "rejected", "a BEL control character is refused where it is",
     scene().replace("name: hostile", "name: hos@@\x07tile"), "U+0007")
case("syntax-escape", "rejected", "an ESC (terminal escape) is refused where it is",
     scene().replace("name: hostile", "name: @@\x1b[31mred"), "U+001B")
case("syntax-del", "rejected", "DEL is refused", "@@\x7f" + scene(), "U+007F")
case("syntax-latin1", "rejected", "a Latin-1 byte is refused as not UTF-8",
     scene().encode().replace(b"name: hostile", b"name: h@@\xe9"), "not valid UTF-8")
case("syntax-unclosed-bracket", "rejected", "an unclosed flow sequence names its bracket",
     scene(bridge=BEAM.replace("[25.0]", "[25.0")), "inside the `[`")
case("syntax-unclosed-brace", "rejected", "an unclosed flow mapping names its brace",
     scene(extra="solver: {time_step: 1e-3\n"), "inside the `{`")
case("syntax-duplicate-key", "rejected", "a duplicate key",
     scene(bridge=BEAM + "  @@spans: [30.0]\n"), "duplicate key `spans`")
case("syntax-two-documents", "rejected", "two YAML documents",
     scene() + "@@---\n" + scene(), "only one YAML document")
case("syntax-merge-key", "rejected", "a merge key",
     "base: &b {x: 1}\nname: m\n@@<<: *b\n" + BEAM + "vehicles:\n" + OSC, "merge keys")
case("syntax-complex-key", "rejected", "a sequence as a key",
     scene() + "? @@[a]\n: 1\n", "keys must be scalars")
case("syntax-deep-nesting", "rejected", "10,000 nested brackets are refused, not a stack overflow",
     "name: " + "[" * 10000 + "]" * 10000 + "\n", "recursion limit")
case("syntax-deep-block-nesting", "rejected", "deep block mappings",
     "".join("  " * i + f"k{i}:\n" for i in range(128)) + "  " * 128 + "@@k: 1\n",
     "nesting deeper")
laughs = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"a{i}: &a{i} [*a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}, *a{i-1}]\n"
    for i in range(1, 6))
case("syntax-billion-laughs", "rejected", "alias expansion is bounded (billion laughs)",
     laughs + "a6: [*a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5]\n", "more than 1000000 nodes")
case("syntax-recursive-alias", "rejected", "an alias to an unfinished anchor",
     "name: &n [@@*n]\n", "recursive alias")
case("syntax-undefined-alias", "rejected", "an alias without anchor",
     "name: @@*nope\n", "")
case("syntax-empty", "rejected", "an empty file", "@@", "the file is empty")
case("syntax-only-comments", "rejected", "a file of comments only", "@@# nothing\n# here\n", "the file is empty")
case("syntax-only-document-marker", "rejected", "a lone `---`", "@@---\n", "the file is empty")
case("syntax-scalar-root", "rejected", "a scalar instead of a mapping", "@@hello\n", "invalid type")
case("syntax-sequence-root", "rejected", "a list instead of a mapping", "@@- a\n- b\n", "invalid type")
case("syntax-long-line", "rejected", "a 200 kB line of garbage is refused quickly",
     "name: x\n" + "z" * 200_000 + "@@: 1\n", "simple key")
case("syntax-bad-indent", "rejected", "a key indented deeper than its siblings",
     scene(bridge=BEAM.replace("  bending_stiffness", "    @@bending_stiffness")), "")

# --- types: every number field fed hostile numbers -------------------------------
float_fields = [
    ("bridge.bending_stiffness", lambda v: scene(bridge=BEAM.replace("8.323e9", "@@" + v))),
    ("bridge.mass_per_length", lambda v: scene(bridge=BEAM.replace("2303.0", "@@" + v))),
    ("bridge.spans[0]", lambda v: scene(bridge=BEAM.replace("[25.0]", "[@@" + v + "]"))),
    ("vehicles[0].sprung_mass", lambda v: scene(vehicles=OSC.replace("5750.0", "@@" + v))),
    ("vehicles[0].stiffness", lambda v: scene(vehicles=OSC.replace("1.595e6", "@@" + v))),
    ("vehicles[0].speed", lambda v: scene(vehicles=OSC.replace("27.7", "@@" + v))),
    ("gravity", lambda v: scene(extra="gravity: @@" + v + "\n")),
    ("solver.time_step", lambda v: scene(extra="solver: {time_step: @@" + v + "}\n")),
]
for path, make in float_fields:
    slug = path.replace(".", "-").replace("[0]", "")
    case(f"float-{slug}-inf", "rejected", f"`.inf` for {path}", make(".inf"), "not a finite number")
    case(f"float-{slug}-nan", "rejected", f"`.nan` for {path}", make(".nan"), "not a finite number")
    case(f"float-{slug}-1e400", "rejected", f"an overflowing literal for {path}", make("1e400"),
         "not a finite number")
    # A speed may carry its unit (`100 km/h`), so its word error says so.
    wrong_type = "in m/s" if path.endswith("speed") else "expected a number"
    case(f"float-{slug}-string", "rejected", f"a word for {path}", make("fast"), wrong_type)
    case(f"float-{slug}-list", "rejected", f"a list for {path}", make("[1, 2]"), wrong_type)

int_fields = [
    ("bridge.elements_per_span", lambda v: scene(bridge=BEAM + "  elements_per_span: @@" + v + "\n")),
    ("bridge.modes.count", lambda v: scene(bridge=BEAM + "  modes: {count: @@" + v + "}\n")),
    ("study.speeds.count", lambda v: scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: 30, count: @@" + v + "}}\n")),
    ("solver.max_iterations", lambda v: scene(extra="solver: {method: iterative, max_iterations: @@" + v + "}\n")),
]
for path, make in int_fields:
    slug = path.replace(".", "-")
    case(f"int-{slug}-2p64", "rejected", f"2^64 for {path} (out of range, no wrap)",
         make("18446744073709551616"), "out of range")
    case(f"int-{slug}-1e40", "rejected", f"a 40-digit integer for {path}",
         make("1" + "0" * 40), "out of range")
    case(f"int-{slug}-negative", "rejected", f"-1 for {path}", make("-1"), "out of range")
    case(f"int-{slug}-float", "rejected", f"2.5 for a whole number ({path})", make("2.5"),
         "expected a whole number")

# Issue 40.6: a count inside the per-span list gets the plain count's
# message at the item; the list's length and `element_length` are checked.
def per_span(v):
    return scene(bridge=BEAM + "  elements_per_span: [@@" + v + "]\n")


case("int-bridge-elements_per_span-list-2p64", "rejected", "2^64 inside the per-span list",
     per_span("18446744073709551616"), "out of range")
case("int-bridge-elements_per_span-list-1e40", "rejected", "a 40-digit integer inside the per-span list",
     per_span("1" + "0" * 40), "out of range")
case("int-bridge-elements_per_span-list-negative", "rejected", "-1 inside the per-span list",
     per_span("-1"), "out of range")
case("int-bridge-elements_per_span-list-float", "rejected", "2.5 inside the per-span list",
     per_span("2.5"), "expected a whole number")
case("size-elements-per-span-list-length", "rejected", "two counts for one span",
     scene(bridge=BEAM + "  elements_per_span: @@[10, 10]\n"), "2 counts for 1 span")
case("size-elements-per-span-list-empty", "rejected", "an empty per-span list",
     scene(bridge=BEAM + "  elements_per_span: @@[]\n"), "0 counts for 1 span")
case("size-element-length-and-count", "rejected", "both `elements_per_span` and `element_length`",
     scene(bridge=BEAM + "  elements_per_span: 10\n  element_length: @@2.5\n"), "not both")
case("size-element-length-tiny", "rejected",
     "an element length of 1e-300 m (a count no integer holds)",
     scene(bridge=BEAM + "  element_length: @@1.0e-300\n"), "more than the 4000 a span takes")

# --- sizes: checked arithmetic and resource budgets ----------------------------------
case("size-plate-terms-wrap", "rejected",
     "plate Ritz terms whose product passes usize (2^32 x 2^32 wrapped to 0 and panicked)",
     scene(bridge=PLATE + "  terms: @@{longitudinal: 4294967296, transverse: 4294967296}\n"),
     "Ritz terms")
case("size-plate-terms-large", "rejected", "plate terms 2000 x 2000",
     scene(bridge=PLATE + "  terms: @@{longitudinal: 2000, transverse: 2000}\n"), "Ritz terms")
case("size-plate-transverse-2000", "budget",
     "2000 transverse plate functions (found by the fuzzer: 50 s inside check)",
     scene(bridge=PLATE + "  terms: @@{longitudinal: 1, transverse: 2000}\n"), "limits.dofs")
case("size-plate-ritz-2000", "budget", "a 40 x 50 plate Ritz basis (15 s inside check)",
     scene(bridge=PLATE + "  terms: @@{longitudinal: 40, transverse: 50}\n"), "limits.dofs")
case("size-sweep-count-2p63", "rejected",
     "a sweep count of 2^63 (its speed list was built after the count was diagnosed)",
     scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: 30, count: @@9223372036854775808}}\n"),
     "needs 1 to")
case("size-sweep-count-1e9", "rejected", "a sweep count of 1e9 (allocated 8 GB inside check)",
     scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: 30, count: @@1000000000}}\n"),
     "needs 1 to")
case("size-beam-20000-dofs", "accepted",
     "a 20,000-DOF beam (died on an allocation unwrap in the dense eigen solver; the sparse one "
     "takes it), as 5 spans of 2,000 elements",
     scene(bridge=BEAM.replace("[25.0]", "[25.0, 25.0, 25.0, 25.0, 25.0]") + "  elements_per_span: @@2000\n"), "")
case("size-elements-per-span-10000", "rejected",
     "10,000 elements on one span: beyond 4,000 the stiffness (conditioned as n⁴) fails the eigen "
     "checks in double precision (found by tests/it/fuzz.rs: mode 112's residual 1.5e-8)",
     scene(bridge=BEAM + "  elements_per_span: @@10000\n"), "between 1 and 4000")
case("size-beam-10000-elements", "accepted", "8,000 elements in two spans (sparse eigen solver)",
     scene(bridge=BEAM.replace("[25.0]", "[25.0, 25.0]") + "  elements_per_span: @@4000\n"), "")
case("size-beam-2000-elements", "accepted",
     "2,000 elements (> 20 s inside check with the dense solver; well under a second now)",
     scene(bridge=BEAM + "  elements_per_span: @@2000\n"), "")
case("size-beam-dofs-budget", "budget", "a 200,000-DOF beam (25 spans of 4,000 elements) is more than the default budget",
     scene(bridge=BEAM.replace("[25.0]", "[" + ", ".join(["25.0"] * 25) + "]") + "  elements_per_span: @@4000\n"), "limits.dofs")
case("size-modes-count", "budget", "more modes than the budget",
     scene(bridge=BEAM + "  elements_per_span: 900\n  modes: {count: @@1000}\n",
           extra="limits: {dofs: 2000}\n"), "limits.modes")
case("size-modes-automatic", "budget",
     "a 10 km span whose automatic cut-off keeps 595 modes (found by tests/it/fuzz.rs with 100 km, "
     "now beyond the plausible span: it used to solve for all of them inside `vbi check`)",
     "name: hostile\nbridge:\n  type: beam\n  spans: @@[10000]\n  bending_stiffness: 8.323e9\n"
     "  mass_per_length: 2303.0\n  elements_per_span: 4000\nvehicles:\n" + OSC, "limits.modes")
case("size-eigen-work", "budget",
     "400 modes of a 16,000-DOF beam (two spans of 4,000 elements): a Lanczos solve of 2.6e9 "
     "(n k²) over the default eigen-work budget of 2e9, refused before solving (an EI = 1 N·m² "
     "span of 10,000 elements, 449 automatic modes of 20,000 DOFs, took 18–30 s inside `vbi check`, "
     "found by tests/it/fuzz.rs)",
     "name: hostile\nbridge:\n  type: beam\n  spans: [25.0, 25.0]\n  bending_stiffness: 8.323e9\n"
     "  mass_per_length: 2303.0\n  elements_per_span: 4000\n  modes: {count: @@400}\nvehicles:\n" + OSC,
     "limits.eigen_work")
case("size-many-spans", "budget",
     "5,000 identical 10 m spans × 2 elements asking 10 modes (issue 23): every band holds 5,000 "
     "nearly equal frequencies, which the Lanczos basis resolves together, so the solve grows as "
     "spans³ (1,000 spans 1.9 s, 2,000 16.7 s, 3,000 53 s inside `vbi check`, minutes at 5,000)",
     "name: hostile\nbridge:\n  type: beam\n  spans: @@[" + ", ".join(["10.0"] * 5000) + "]\n"
     "  bending_stiffness: 8.323e9\n  mass_per_length: 2303.0\n  elements_per_span: 2\n"
     "  modes: {count: 10}\nvehicles:\n" + OSC, "limits.eigen_work")
case("size-modes-max-frequency", "budget", "a cut-off frequency that keeps all 600 modes",
     scene(bridge=BEAM + "  elements_per_span: 300\n  modes: @@{max_frequency: 1.0e12}\n",
           extra="solver: {time_step: 1.0e-3}\n"), "limits.modes")
case("size-steps-2e7", "budget", "2e7 time steps (> 20 s)",
     scene(extra="solver: {time_step: @@4.5e-8}\n"), "limits.steps")
case("size-steps-1.8e8", "budget", "1.8e8 steps (a history preallocated for all of them)",
     scene(extra="solver: {time_step: @@5.0e-9}\n"), "limits.steps")
case("size-steps-free-vibration", "budget", "a free vibration of a day at 1e-4 s",
     scene(extra="solver: {time_step: 1.0e-4, free_vibration: @@1000.0}\n"), "limits.steps")
case("size-steps-slow-vehicle", "budget", "a vehicle at 1 mm/s gives too many steps",
     scene(vehicles=OSC.replace("27.7", "0.001"), extra="solver: {time_step: @@1.0e-3}\n"),
     "limits.steps")
case("size-axles-100000", "budget", "100,000 axles",
     scene(vehicles="  @@- type: moving_force\n    loads: [" + ", ".join(["1e4"] * 100_000)
           + "]\n    axle_spacings: [" + ", ".join(["1"] * 99_999) + "]\n    speed: 20.0\n"),
     "limits.wheels")
case("size-vehicles-2000", "budget", "2,000 vehicles",
     "name: many\n" + BEAM + "vehicles:\n" + "".join(
         ("  @@- {" if i == 0 else "  - {") + f"type: moving_force, loads: [1.0e4], speed: 20.0, entry_time: {i * 0.01}}}\n"
         for i in range(2000)), "limits.wheels")
case("size-records-20000", "budget", "20,000 records",
     scene(extra="record:\n" + "".join(
         ("  @@- {" if i == 0 else "  - {") + f"name: r{i}, quantity: bridge_displacement, x: 12.5}}\n" for i in range(20000))),
     "limits.records")
case("size-sweep-points", "budget", "a 99,000-run sweep",
     scene(bridge=BEAM, extra="surface: {type: random, class: good}\n"
           "study: @@{type: speed_sweep, speeds: {from: 10, to: 30, count: 495}, samples: 200}\n"),
     "limits.study_points")
case("size-map-points", "budget", "a 250,000-point separation map",
     "name: map\n" + BEAM + "vehicles:\n  - type: oscillator\n    dimensionless: "
     "{velocity_ratio: 0.3, mass_ratio: 1.0, frequency_ratio: 0.5}\ncontact: {type: rigid}\n"
     "study: @@{type: separation_map, velocity_ratio: {from: 0.05, to: 1.0, count: 500}, "
     "mass_ratio: {from: 0.1, to: 2.0, count: 500}}\n", "limits.study_points")
case("size-road-terms", "budget", "a random road of 1e6 terms",
     scene(extra="surface: {type: random, class: good, terms: @@1000000}\n"), "limits.road_terms")
case("size-track-grid", "budget", "an FRA track sampled at 1e-9 m",
     scene(extra="surface: {type: fra, class: 5, shortest_wavelength: @@1.0e-9, terms: 100}\n"),
     "limits.profile_points")
case("size-track-work", "budget", "an FRA track of 20,000 terms on a 0.2 mm grid (5e9 multiply-adds)",
     scene(extra="surface: {type: fra, class: 5, shortest_wavelength: 0.002, terms: @@20000}\n"),
     "limits.profile_work")
case("size-road-work", "budget", "a power-law road of 19,000 terms (1.2e10 multiply-adds for its period grid)",
     scene(extra="surface: {type: random, class: good, terms: @@19000}\n"), "limits.profile_work")
case("size-track-terms", "budget", "an FRA track of 1e6 terms",
     scene(extra="surface: {type: fra, class: 5, terms: @@1000000}\n"), "limits.road_terms")
case("size-road-sampling", "budget", "a random road sampled over 1e12 m",
     scene(extra="surface: {type: random, class: good, sampling_length: @@1.0e12}\n"),
     "limits.road_terms")
case("size-output-bytes", "budget", "a history CSV of gigabytes",
     scene(extra="solver: {time_step: 1.0e-6}\nlimits: {steps: 1.0e8}\nrecord:\n" + "".join(
         ("  @@- {" if i == 0 else "  - {") + f"name: r{i}, quantity: bridge_acceleration, x: 12.5}}\n" for i in range(100))),
     "limits.output_bytes")
case("size-study-steps", "budget", "a study whose runs add up to too many steps",
     scene(extra="solver: {time_step: 1.0e-6}\n"
           "study: @@{type: speed_sweep, speeds: {from: 10, to: 30, count: 300}}\n"),
     "limits.study_steps")
case("size-limit-zero", "rejected", "a limit of 0", scene(extra="limits: {steps: @@0}\n"),
     "a limit must be")
case("size-limit-fraction", "rejected", "a fractional limit",
     scene(extra="limits: {wheels: @@2.5}\n"), "a limit must be")
case("size-limit-unknown", "rejected", "an unknown limit",
     scene(extra="limits: {@@cpu: 1}\n"), "unknown field `cpu`")
case("size-elements-2p63", "rejected", "elements per span of 2^63",
     scene(bridge=BEAM + "  elements_per_span: @@9223372036854775807\n"), "elements per span")

# --- names and output folder ------------------------------------------------------
case("name-empty", "rejected", "an empty name", scene(name="@@''"), "must not be empty")
case("name-control-char", "rejected", "a name with a control character",
     scene(name='@@"a\\x01b"'), "control character")
case("name-newline", "rejected", "a name with a line break", scene(name='@@"a\\nb"'),
     "control character")
case("name-too-long", "rejected", "a 10,000-character name", scene(name="@@" + "n" * 10000),
     "characters")
case("record-name-control", "rejected", "a record name with a control character",
     scene(extra='record:\n  - {name: @@"a\\tb", quantity: bridge_displacement, x: 12.5}\n'),
     "control character")
case("record-name-slash", "accepted", "a record name with a slash is a column, not a file",
     scene(extra="record:\n  - {name: a/b, quantity: bridge_displacement, x: 12.5}\n"))
case("record-name-duplicate", "rejected", "duplicate record names",
     scene(extra="record:\n  - {name: a, quantity: bridge_displacement, x: 12.5}\n"
           "  - {name: @@a, quantity: bridge_displacement, x: 10.0}\n"), "duplicate record name")

# --- physics plausibility -------------------------------------------------------
case("phys-stiffness-1e20", "rejected", "a suspension of 1e20 N/m (ran to -355 m/s^2)",
     scene(vehicles=OSC.replace("1.595e6", "@@1e20")), "physically plausible range")
case("phys-stiffness-1e308", "rejected", "a suspension of 1e308 N/m",
     scene(vehicles=OSC.replace("1.595e6", "@@1e308")), "physically plausible range")
case("phys-contact-ratio-1e308", "rejected",
     "a contact stiffness ratio of 1e308 (overflowed to infinity and exited 0)",
     scene(extra="contact: {type: elastic, stiffness_ratio: @@1e308}\n"), "")
case("phys-contact-stiffness-1e20", "rejected", "an elastic contact of 1e20 N/m",
     scene(extra="contact: {type: elastic, stiffness: @@1e20}\n"), "physically plausible range")
case("phys-hertz-1e30", "rejected", "a Hertz coefficient of 1e30",
     scene(extra="contact: @@{type: hertz, coefficient: 1e30}\n"), "physically plausible range")
case("phys-mass-microgram", "rejected", "a sprung mass of a microgram",
     scene(vehicles=OSC.replace("5750.0", "@@1e-9")), "physically plausible range")
case("phys-mass-mountain", "rejected", "a sprung mass of a mountain (1e15 kg)",
     scene(vehicles=OSC.replace("5750.0", "@@1e15")), "physically plausible range")
case("phys-unsprung-mountain", "rejected", "an unsprung mass of 1e15 kg",
     scene(vehicles=OSC + "    unsprung_mass: @@1e15\n"), "physically plausible range")
case("phys-load-1e12", "rejected", "an axle load of 1e12 N",
     scene(vehicles="  - {type: moving_force, loads: [@@1e12], speed: 20.0}\n"),
     "physically plausible range")
case("phys-ei-1e20", "rejected", "a bending stiffness of 1e20 N m^2",
     scene(bridge=BEAM.replace("8.323e9", "@@1e20")), "physically plausible range")
case("phys-mass-per-length-1e12", "rejected", "1e12 kg/m",
     scene(bridge=BEAM.replace("2303.0", "@@1e12")), "physically plausible range")
case("phys-gravity-1e5", "rejected", "gravity of 1e5 m/s^2",
     scene(extra="gravity: @@1e5\n"), "physically plausible range")
case("phys-speed-2e8", "rejected", "a speed of 2e8 m/s",
     scene(vehicles=OSC.replace("27.7", "@@2e8")), "above 1000")
case("phys-map-speed-2e8", "rejected",
     "velocity ratios giving 2e8 m/s inside a separation map (a single scene refuses > 1000 m/s)",
     "name: map\n" + BEAM + "vehicles:\n  - type: oscillator\n    dimensionless: "
     "{velocity_ratio: 0.3, mass_ratio: 1.0, frequency_ratio: 0.5}\ncontact: {type: rigid}\n"
     "study: {type: separation_map, velocity_ratio: {from: 0.05, to: @@1.0e6, count: 5}, "
     "mass_ratio: {from: 0.1, to: 2.0, count: 5}}\n", "gives a speed")
case("phys-map-mass-ratio-1e12", "rejected", "mass ratios giving a mountain inside a map",
     "name: map\n" + BEAM + "vehicles:\n  - type: oscillator\n    dimensionless: "
     "{velocity_ratio: 0.3, mass_ratio: 1.0, frequency_ratio: 0.5}\ncontact: {type: rigid}\n"
     "study: {type: separation_map, velocity_ratio: {from: 0.05, to: 1.0, count: 5}, "
     "mass_ratio: {from: 0.1, to: @@1.0e12, count: 5}}\n", "physically plausible range")
case("phys-sweep-speed-2e8", "rejected", "a sweep to 2e8 m/s",
     scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: @@2e8, count: 5}}\n"), "above 1000")
case("phys-start-position-1e308", "rejected",
     "a start position of -1e308 m (was blamed on the time step at 2:1)",
     scene(vehicles=OSC + "    start_position: @@-1e308\n"), "physically plausible range")
case("phys-entry-time-1e9", "rejected", "an entry time of 1e9 s (a CSV of gigabytes)",
     scene(vehicles=OSC + "    entry_time: @@1e9\n"), "physically plausible range")
case("phys-entry-time-long", "rejected", "an entry time of two days",
     scene(vehicles=OSC + "    entry_time: @@172800\n"), "physically plausible range")
# Issue 23, point 4: the ranges that were still missing.
case("phys-plate-thickness-1e5", "rejected", "a plate 100 km thick",
     scene(bridge=PLATE.replace("thickness: 0.2", "thickness: @@1e5")),
     "outside the physically plausible range 0.001 to 100 m (from laboratory strips")
case("phys-plate-width-1e6", "rejected", "a deck 1,000 km wide",
     scene(bridge=PLATE.replace("width: 13.0", "width: @@1e6")),
     "outside the physically plausible range 0.01 to 1000 m (a laboratory strip")
case("phys-plate-density-1e9", "rejected", "a plate density of 1e9 kg/m^3",
     scene(bridge=PLATE.replace("mass_per_area: 500.0", "density: @@1e9")),
     "outside the physically plausible range 1 to 100000 kg/m³ (aerogels")
case("phys-time-step-1e-15", "rejected", "an explicit time step of a femtosecond",
     scene(extra="solver: {time_step: @@1e-15}\n"),
     "outside the physically plausible range 1e-9 to 1 s (a nanosecond")
case("phys-time-step-1e3", "rejected", "an explicit time step of 1000 s",
     scene(extra="solver: {time_step: @@1e3}\n"),
     "outside the physically plausible range 1e-9 to 1 s")
case("phys-rayleigh-frequency-1e9", "rejected", "Rayleigh damping matched at 1 GHz",
     scene(bridge=BEAM + "  damping: {type: rayleigh, frequencies: [2.0, @@1e9], ratio: 0.02}\n"),
     "outside the physically plausible range 0.001 to 100000 Hz (the longest suspension")
case("phys-rayleigh-frequency-1e-9", "rejected", "Rayleigh damping matched at 1 nHz",
     scene(bridge=BEAM + "  damping: {type: rayleigh, frequencies: [@@1e-9, 20.0], ratio: 0.02}\n"),
     "outside the physically plausible range 0.001 to 100000 Hz")
case("phys-lateral-position-1e6", "rejected", "a vehicle 1,000 km across a 13 m deck",
     scene(bridge=PLATE, vehicles="  - {type: moving_force, loads: [1.0e5], speed: 20.0, "
           "lateral_position: @@1.0e6}\n"),
     "fall off the deck, which spans 0 to 13 m")

# --- many errors at once ----------------------------------------------------------
many = "name: many\n" + BEAM + "vehicles:\n" + "".join(
    f"  - {{type: oscillator, sprung_mass: {-1 - i}, stiffness: 1.0e6, speed: 20.0}}\n"
    for i in range(200))
case("many-semantic-errors", "budget", "200 vehicles with a negative mass each (wheels within budget? no)",
     many.replace("  - {", "  @@- {", 1) + "limits: {wheels: 100}\n", "limits.wheels")
case("many-semantic-errors-shown-capped", "rejected",
     "200 negative masses: 50 shown and a count of the rest",
     many.replace("sprung_mass: -1,", "sprung_mass: @@-1,", 1), "150 more errors not shown")
typos = "name: typos\n" + BEAM + "vehicles:\n" + "".join(
    f"  - {{type: oscillator, sprung_mas: 1.0, stiffness: 1.0e6, speed: 20.0}}\n" for i in range(20))
case("many-type-errors", "rejected", "20 unknown keys are all reported, not only the first",
     typos.replace("sprung_mas", "@@sprung_mas", 1), "unknown field `sprung_mas`")
big = "name: big\n" + BEAM + "vehicles:\n" + "".join(
    f"  - {{type: oscillator, sprung_mass: -1.0, stiffness: 1.0e6, speed: 20.0}}\n"
    for i in range(20000)) + "limits: {wheels: 100000}\n"
case("many-errors-20000", "budget",
     "20,000 errors in one file (diagnostics were quadratic: 15 s for 1.5 MB); the file raises "
     "its wheel limit, refused without `--trust-limits` (tests/it/hostile.rs runs it with it)",
     big.replace("  - {type", "  @@- {type", 1), "--trust-limits")

# --- structure: keys, variants, references ------------------------------------------
structural = [
    ("unknown-top-key", scene(extra="@@colour: red\n"), "unknown field `colour`"),
    ("unknown-bridge-type", scene(bridge=BEAM.replace("type: beam", "type: @@truss")), "unknown variant `truss`"),
    ("bridge-type-list", scene(bridge=BEAM.replace("type: beam", "type: @@[beam]")), "must name a variant"),
    ("missing-name", scene().replace("name: hostile\n", "") .replace("bridge:", "@@bridge:", 1), "missing field `name`"),
    ("vehicles-empty", scene(vehicles="").replace("vehicles:\n", "vehicles: @@[]\n"), "at least one vehicle"),
    ("vehicles-null", scene(vehicles="").replace("vehicles:\n", "vehicles@@:\n"), "invalid type"),
    ("record-vehicle-huge", scene(extra="record:\n  - {name: f, quantity: contact_force, vehicle: @@18446744073709551615, wheel: 1}\n"), "vehicle"),
    ("record-wheel-zero", scene(extra="record:\n  - {name: f, quantity: contact_force, vehicle: 1, wheel: @@0}\n"), "wheel"),
    ("record-x-inf", scene(extra="record:\n  - {name: f, quantity: bridge_displacement, x: @@.inf}\n"), "not a finite number"),
    ("record-x-off", scene(extra="record:\n  - {name: f, quantity: bridge_displacement, x: @@1e300}\n"), "off the bridge"),
    ("spans-empty", scene(bridge=BEAM.replace("spans: [25.0]", "spans: @@[]")), "at least one span"),
    ("spans-tiny", scene(bridge=BEAM.replace("[25.0]", "[25.0, @@1e-300]")), "1/1000"),
    ("spans-huge", scene(bridge=BEAM.replace("spans: [25.0]", "spans: @@[1e300]")), "100 km"),
    ("axle-spacing-mismatch", scene(vehicles="  - {type: moving_force, loads: [1e4, 1e4], axle_spacings: @@[1, 2, 3], speed: 20}\n"), "axle spacings"),
    ("newmark-alpha", scene(extra="solver: {newmark: {alpha: @@-5}}\n"), "HHT"),
    ("damping-ratio-2", scene(bridge=BEAM + "  damping: {type: modal, ratio: @@2}\n"), "damping ratio"),
    ("sweep-samples-huge", scene(extra="surface: {type: random, class: good}\nstudy: @@{type: speed_sweep, speeds: {from: 10, to: 30, count: 5}, samples: 18446744073709551615}\n"), "limits.study_points"),
    ("sweep-span-huge", scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: 30, count: 5}, span: @@18446744073709551615}\n"), "does not exist"),
    ("sweep-girder-huge", scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: 30, count: 5}, girder: @@99999}\n"), "does not exist"),
    ("sweep-roughness-repeated", scene(extra="study: {type: speed_sweep, speeds: {from: 10, to: 30, count: 5}, roughness: [good, @@good]}\n"), "listed twice"),
    ("plate-lateral-inf", scene(bridge=PLATE, vehicles=OSC + "    lateral_position: @@.inf\n"), "not a finite number"),
    ("plate-girder-off", scene(bridge=PLATE + "  girder_lines: [@@1e300]\n"), "off the deck"),
    ("random-terms-zero", scene(extra="surface: {type: random, class: good, terms: @@0}\n"), "between 1 and"),
    ("random-seed-negative", scene(extra="surface: {type: random, class: good, seed: @@-1}\n"), "out of range"),
    ("harmonic-wavelength-zero", scene(extra="surface: {type: harmonic, amplitude: 0.001, wavelength: @@0}\n"), "must be positive"),
    ("fra-class-7", scene(extra="surface: {type: fra, class: @@7}\n"), "1 (worst) to 6 (best)"),
    ("fra-class-huge", scene(extra="surface: {type: fra, class: @@300}\n"), "out of range"),
    ("fra-band-negative", scene(extra="surface: {type: fra, class: 5, longest_wavelength: @@-80}\n"), "must be positive"),
    ("german-band-empty", scene(extra="surface: {type: german, interference: high, shortest_wavelength: 50, longest_wavelength: @@5}\n"), "band is empty"),
    ("iso-class-unknown", scene(extra="surface: {type: iso8608, class: @@Z}\n"), "unknown variant"),
    ("measured-missing", scene(extra="surface: {type: measured, file: @@no-such-profile.csv}\n"), "cannot read"),
    ("measured-directory", scene(extra="surface: {type: measured, file: @@.}\n"), "is not a regular file"),
    ("dip-depth-zero", scene(extra="surface: {type: dip, start: 2, length: 1, depth: @@0}\n"), "must be positive"),
    ("piecewise-one-point", scene(extra="surface: {type: piecewise_linear, points: @@[[0, 0]]}\n"), "at least two"),
    # Issue 22: a run-in far longer than any approach (vehicles are placed before it).
    ("run-in-huge", scene(extra="surface: {type: fra, class: 5, run_in: @@1.0e12}\n"), "limits.profile_points"),
    # Issue 23: features shorter than a step's travel are missed between steps.
    ("bump-shorter-than-step", scene(extra="surface: {type: bump, start: 2, length: @@1e-300, height: 0.01}\nsolver: {time_step: 1.0e-4}\n"), "shorter than the"),
    ("ramp-shorter-than-step", scene(extra="surface: {type: ramp, start: 2, length: @@1e-6, height: 0.01}\n"), "would miss it"),
    ("harmonic-aliased", scene(extra="surface: {type: harmonic, amplitude: 0.001, wavelength: @@1e-3}\nsolver: {time_step: 1.0e-4}\n"), "shorter than twice"),
    ("piecewise-segment-shorter-than-step", scene(extra="surface: {type: piecewise_linear, points: [[0, 0], [5, 0], @@[5.000001, 0.01], [30, 0.01]]}\nsolver: {time_step: 1.0e-4}\n"), "type: step"),
    ("dimensionless-velocity-huge", "name: d\n" + BEAM + "vehicles:\n  - type: oscillator\n    dimensionless: {velocity_ratio: 1e9, mass_ratio: 1.0, frequency_ratio: 0.5}\n".replace("velocity_ratio: 1e9", "velocity_ratio: @@1e9"), "above 1000"),
]
for slug, text, message in structural:
    outcome = "budget" if message.startswith("limits.") else "rejected"
    case("struct-" + slug, outcome, slug.replace("-", " "), text, message)

# Ground-motion records: data files written beside the cases.
AT2_HEAD = ("PEER NGA STRONG MOTION DATABASE RECORD\nhostile\n"
            "ACCELERATION TIME SERIES IN UNITS OF G\n")
side_files = {
    "quake-huge-npts.AT2": AT2_HEAD + "NPTS= 1000000000000, DT= .0100 SEC\n0.1 0.2\n",
    "quake-short.AT2": AT2_HEAD + "NPTS=   10, DT= .0100 SEC\n0.1 0.2 0.3\n",
    "quake-nan.csv": "time [s], acceleration [g]\n0, 0\n0.01, nan\n",
    "quake-backwards.csv": "time [s], acceleration [g]\n0, 0\n0.02, 0.1\n0.01, 0.1\n",
    "quake-no-units.csv": "0, 0\n0.01, 0.1\n",
    "quake-ok.csv": "time [s], acceleration [g]\n0, 0\n0.01, 0.1\n0.02, 0\n",
    # Issue 23: record intervals outside any accelerograph's.
    "quake-interval-huge.AT2": AT2_HEAD + "NPTS=    3, DT= 1e300 SEC\n0.1 0.2 0.3\n",
    "quake-interval-huge.csv": "time [s], acceleration [g]\n0, 0\n1e300, 0.1\n",
}
ground = [
    ("huge-npts", "{file: @@quake-huge-npts.AT2}", "NPTS = 1000000000000"),
    ("short-at2", "{file: @@quake-short.AT2}", "declares NPTS = 10"),
    ("nan", "{file: @@quake-nan.csv}", "quake-nan.csv:3: column 2"),
    ("backwards", "{file: @@quake-backwards.csv}", "must increase strictly"),
    ("no-units", "{file: @@quake-no-units.csv}", "does not state the units"),
    ("missing", "{file: @@no-such-record.AT2}", "cannot read"),
    ("interval-huge-at2", "{file: @@quake-interval-huge.AT2}", "quake-interval-huge.AT2:4: DT = 1e300 s is outside the plausible sampling interval"),
    ("interval-huge-csv", "{file: @@quake-interval-huge.csv}", "quake-interval-huge.csv:3: column 1"),
    ("lateral", "{file: quake-ok.csv, direction: @@lateral}", "lateral bridge modes"),
    ("scale-nan", "{file: quake-ok.csv, scale: @@.nan}", "finite"),
    ("units-disagree", "{file: quake-ok.csv, units: @@m/s^2}", "disagrees"),
]
for slug, component, message in ground:
    case("ground-" + slug, "rejected", "ground motion: " + slug.replace("-", " "),
         scene(extra="ground_motion:\n  - " + component + "\n"), message)


# --- imported FE bridges (issue 12): the matrices and tables live in
# tests/hostile/cases/fe/ (written below), inside the scenes' folder tree
# (issue 23: a scene reads nothing outside it), the scenes refer to them by fe/.
FE = os.path.join(CASES, "fe")
MM = "%%MatrixMarket matrix coordinate real symmetric\n"
FE_FILES = {
    "K.mtx": MM + "2 2 3\n1 1 2.0e6\n2 1 -1.0e6\n2 2 2.0e6\n",
    "M.mtx": MM + "2 2 2\n1 1 100.0\n2 2 100.0\n",
    "dofs.csv": "dof,node,direction\n1,1,uz\n2,2,uz\n",
    "rail.csv": "node,x\n1,0.0\n2,5.0\n",
    "K-huge-entries.mtx": MM + "2 2 1000000000000\n1 1 2.0e6\n",
    "K-huge-rows.mtx": MM + "1000000000 1000000000 3\n1 1 2.0e6\n",
    "K-truncated.mtx": MM + "2 2 3\n1 1 2.0e6\n2 1 -1.0e6\n",
    "K-range.mtx": MM + "2 2 3\n1 1 2.0e6\n3 1 -1.0e6\n2 2 2.0e6\n",
    "K-unsymmetric.mtx": "%%MatrixMarket matrix coordinate real general\n2 2 4\n"
                         "1 1 2.0e6\n2 1 -1.0e6\n1 2 -2.0e6\n2 2 2.0e6\n",
    "K-pattern.mtx": "%%MatrixMarket matrix coordinate pattern symmetric\n2 2 1\n1 1\n",
    "M-nan.mtx": MM + "2 2 2\n1 1 NaN\n2 2 100.0\n",
    "rail-backwards.csv": "node,x\n1,5.0\n2,0.0\n",
    "rail-unknown.csv": "node,x\n1,0.0\n7,5.0\n",
    # Issue 23: repeated entries, in each format where they can occur.
    "K-repeated.mtx": "%%MatrixMarket matrix coordinate real general\n2 2 5\n"
                      "1 1 2.0e6\n2 1 -1.0e6\n1 2 -1.0e6\n2 2 2.0e6\n1 1 2.0e6\n",
    "K-both-triangles.mtx": MM + "2 2 4\n1 1 2.0e6\n2 1 -1.0e6\n1 2 -1.0e6\n2 2 2.0e6\n",
    "K-repeated.abq": "** K\n1,3, 1,3, 2.0e6\n2,3, 1,3, -1.0e6\n2,3, 2,3, 2.0e6\n2,3, 1,3, -1.0e6\n",
    "M.abq": "1,3, 1,3, 100.0\n2,3, 2,3, 100.0\n",
    "K-repeated.hb": "two DOFs" + " " * 64 + "KEY     \n"
                     + "".join(f"{v:>14}" for v in (3, 1, 1, 1, 0)) + "\n"
                     + "RSA" + "".join(f"{v:>14}" for v in ("", 2, 2, 3, 0))[3:] + "\n"
                     + "(4I8)           (4I8)           (4E10.3)            \n"
                     + "       1       3       4\n       1       1       2\n"
                     + " 2.000E+06-1.000E+06 2.000E+06\n",
    "C-unsymmetric.mtx": "%%MatrixMarket matrix coordinate real general\n2 2 4\n"
                         "1 1 2.0e3\n2 1 -1.0e3\n1 2 -2.0e3\n2 2 2.0e3\n",
}


def textbook_beam(elements=4, length=10.0, ei=1.0e9, m=1000.0):
    """A simply supported beam's K and M (uz, θ per node, θ = +dw/dx: the
    textbook Hermite element), lower triangles in Matrix Market form."""
    h = length / elements
    ke = [[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
          [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]]
    me = [[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
          [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]]
    n = 2 * (elements + 1)
    k, mass = {}, {}
    for e in range(elements):
        for a in range(4):
            for b in range(4):
                r, c = 2 * e + a, 2 * e + b
                if r >= c:
                    k[(r, c)] = k.get((r, c), 0.0) + ei / h ** 3 * ke[a][b]
                    mass[(r, c)] = mass.get((r, c), 0.0) + m * h / 420 * me[a][b]

    def mtx(entries):
        lines = [f"{r + 1} {c + 1} {v!r}" for (r, c), v in sorted(entries.items()) if v != 0.0]
        return MM + f"{n} {n} {len(lines)}\n" + "\n".join(lines) + "\n"
    dofs = "dof,node,direction\n" + "".join(
        f"{2 * i + 1},{i + 1},uz\n{2 * i + 2},{i + 1},ry\n" for i in range(elements + 1))
    rail = "node,x\n" + "".join(f"{i + 1},{i * h!r}\n" for i in range(elements + 1))
    return mtx(k), mtx(mass), dofs, rail


(FE_FILES["K-textbook.mtx"], FE_FILES["M-textbook.mtx"],
 FE_FILES["dofs-beam.csv"], FE_FILES["rail-beam.csv"]) = textbook_beam()


def fe_scene(stiffness="fe/K.mtx", mass="fe/M.mtx", rail="fe/rail.csv"):
    bridge = ("bridge:\n  type: fe_import\n  stiffness: " + stiffness + "\n  mass: " + mass
              + "\n  dof_map: fe/dofs.csv\n  rails: [{name: rail, file: " + rail + "}]\n")
    return scene(bridge=bridge, vehicles="  - {type: moving_force, speed: 10.0, loads: [1.0e4]}\n")


case("ok-fe-import", "accepted", "a two-DOF imported model with its rail", fe_scene())
case("fe-huge-entries", "rejected",
     "a Matrix Market header declaring 10^12 entries is refused before anything is allocated",
     fe_scene(stiffness="@@fe/K-huge-entries.mtx"), "K-huge-entries.mtx:2: the size line declares")
case("fe-huge-rows", "rejected",
     "a Matrix Market header declaring 10^9 rows is refused before anything is allocated",
     fe_scene(stiffness="@@fe/K-huge-rows.mtx"), "declares 1000000000 rows")
case("fe-truncated", "rejected", "a matrix file that ends before its declared entries",
     fe_scene(stiffness="@@fe/K-truncated.mtx"), "K-truncated.mtx:4: the file ends after 2 of the 3")
case("fe-out-of-range", "rejected", "an entry index beyond the declared order",
     fe_scene(stiffness="@@fe/K-range.mtx"), "K-range.mtx:4:1: index 3 is outside 1")
case("fe-unsymmetric", "rejected", "a general matrix that is not symmetric",
     fe_scene(stiffness="@@fe/K-unsymmetric.mtx"),
     "K-unsymmetric.mtx:5:1: the matrix is not symmetric: entry (1, 2) = -2000000 but (2, 1) = -1000000 at line 4")
case("fe-pattern", "rejected", "a pattern matrix has no values",
     fe_scene(stiffness="@@fe/K-pattern.mtx"), "`pattern` entries are not read")
case("fe-nan", "rejected", "a NaN mass entry",
     fe_scene(mass="@@fe/M-nan.mtx"), "M-nan.mtx:3:5: `NaN` is not a finite number")
case("fe-missing", "rejected", "a matrix file that does not exist",
     fe_scene(mass="@@fe/none.mtx"), "cannot read")
case("fe-rail-backwards", "rejected", "a rail whose x does not increase",
     fe_scene(rail="@@fe/rail-backwards.csv"), "rail-backwards.csv:3:2")
case("fe-rail-unknown-node", "rejected", "a rail node missing from the DOF map",
     fe_scene(rail="fe/rail-unknown.csv"), "node 7 is not in the DOF map")
case("fe-repeated-general", "rejected",
     "an entry given twice in a general Matrix Market file is refused, not summed (issue 23)",
     fe_scene(stiffness="@@fe/K-repeated.mtx"),
     "K-repeated.mtx:7:1: entry (1, 1) (node 1 uz, node 1 uz) repeats entry (1, 1) of line 3")
case("fe-repeated-both-triangles", "rejected",
     "a symmetric Matrix Market file giving an entry in both triangles (issue 23)",
     fe_scene(stiffness="@@fe/K-both-triangles.mtx"),
     "K-both-triangles.mtx:5:1: entry (1, 2) (node 1 uz, node 2 uz) repeats entry (2, 1) of line 4")
case("fe-repeated-harwell-boeing", "rejected",
     "a Harwell-Boeing column listing a row twice (issue 23)",
     fe_scene(stiffness="@@fe/K-repeated.hb"),
     "K-repeated.hb:7:11: entry (1, 1) (node 1 uz, node 1 uz) repeats entry (1, 1) of line 7")
case("fe-repeated-abaqus", "rejected", "an Abaqus entry line given twice (issue 23)",
     scene(bridge="bridge:\n  type: fe_import\n  stiffness: @@fe/K-repeated.abq\n"
           "  mass: fe/M.abq\n  rails: [{name: rail, file: fe/rail.csv}]\n",
           vehicles="  - {type: moving_force, speed: 10.0, loads: [1.0e4]}\n"),
     "K-repeated.abq:5:1: entry (2, 1) (node 2 uz, node 1 uz) repeats entry (2, 1) of line 3")
case("fe-damping-unsymmetric", "rejected",
     "an unsymmetric damping matrix is located in its own file (issue 23)",
     fe_scene().replace("  rails:", "  damping: {type: matrix, file: @@fe/C-unsymmetric.mtx}\n  rails:"),
     "C-unsymmetric.mtx:5:1: the matrix is not symmetric: entry (1, 2) = -2000 but (2, 1) = -1000 at line 4")


def beam_scene(extra="", at=""):
    bridge = ("bridge:\n  " + at + "type: fe_import\n" + extra
              + "  stiffness: fe/K-textbook.mtx\n  mass: fe/M-textbook.mtx\n"
              "  dof_map: fe/dofs-beam.csv\n"
              "  constrained: [{node: 1, direction: uz}, {node: 5, direction: uz}]\n"
              "  rails: [{name: rail, file: fe/rail-beam.csv}]\n")
    return scene(bridge=bridge, vehicles="  - {type: moving_force, speed: 10.0, loads: [1.0e4]}\n")


case("fe-rotation-textbook", "rejected",
     "a textbook beam (theta = +dw/dx written as ry) is refused where rotation_sign belongs (issue 22)",
     beam_scene(at="@@"),
     "rail `rail`: the stiffness says ∂w/∂x = +ry (a textbook beam's θ) on 2 of its 4 segments")
case("ok-fe-rotation-declared", "accepted",
     "the textbook beam with `rotation_sign: {ry: -1}` (issue 22)",
     beam_scene(extra="  rotation_sign: {ry: -1}\n"))
case("fe-rotation-sign-value", "rejected", "a rotation sign other than -1 or 1",
     beam_scene(extra="  rotation_sign: {ry: @@2}\n"), "a rotation's sign is -1 or 1, got 2")
# Issue 23, point 4: a rail listing every other node of the beam: no element
# joins two consecutive rail nodes, so no segment can tell the rotations' sign.
FE_FILES["rail-skipping.csv"] = "node,x\n1,0.0\n3,5.0\n5,10.0\n"
case("fe-rotation-no-evidence", "rejected",
     "a rail whose nodes no element joins: the rotation sign cannot be checked, refused with "
     "the reason unless `rotation_sign` confirms it (issue 23)",
     beam_scene(at="@@").replace("fe/rail-beam.csv", "fe/rail-skipping.csv"),
     "rail `rail`: the sign convention of its ry rotations cannot be checked")
case("ok-fe-rotation-no-evidence-declared", "accepted",
     "the same rail with the convention confirmed by `rotation_sign` (issue 23)",
     beam_scene(extra="  rotation_sign: {ry: -1}\n").replace("fe/rail-beam.csv",
                                                             "fe/rail-skipping.csv"))


# --- confined reads (issue 23): paths out of the scene's folder by `../`, by
# a symlink or absolute, to a device, and a canary file beside the cases'
# folder (tests/hostile/canary.txt) whose content must never appear in any
# output (tests/it/hostile.rs checks every case for it). Each is refused at the
# key that names the file, with the path and `--data-dir`, before it is read.
CANARY = "CANARY-SECRET-8a41f2"
CANARY_TEXT = ("root:x:0:0:root:/root:/bin/bash " + CANARY + "\n"
               + CANARY + "," + CANARY + "\n1," + CANARY + "\n")
# Symlinks in the cases' folder (made by main()): name -> target.
SYMLINKS = {
    "link-canary.csv": "../canary.txt",
    "link-canary.AT2": "../canary.txt",
    "link-zero.AT2": "/dev/zero",
    "link-passwd.mtx": "/etc/passwd",
}
OUTSIDE = "outside the scene's folder"
ABSOLUTE = "is an absolute path"
for slug, component, message in [
    ("traversal-record", "{file: @@../canary.txt}", OUTSIDE),
    ("traversal-deep", "{file: @@fe/../../canary.txt}", OUTSIDE),
    ("symlink-record", "{file: @@link-canary.AT2}", "through a symlink"),
    ("symlink-device", "{file: @@link-zero.AT2}", OUTSIDE),
    ("absolute-record", "{file: @@/etc/passwd}", ABSOLUTE),
    ("absolute-device", "{file: @@/dev/zero}", ABSOLUTE),
]:
    case("confine-" + slug, "rejected", "confined reads: a ground-motion record, " + slug,
         scene(extra="ground_motion:\n  - " + component + "\n"), message)
for slug, surface, message in [
    ("traversal-profile", "{type: measured, file: @@../canary.txt}", OUTSIDE),
    ("symlink-profile", "{type: measured, file: @@link-canary.csv}", "through a symlink"),
    ("absolute-profile", "{type: measured, file: @@/proc/self/environ}", ABSOLUTE),
    ("folder-profile", "{type: measured, file: @@fe}", "not a regular file"),
]:
    case("confine-" + slug, "rejected", "confined reads: a measured profile, " + slug,
         scene(extra="surface: " + surface + "\n"), message)
case("confine-traversal-matrix", "rejected", "confined reads: a stiffness matrix by `../`",
     fe_scene(stiffness="@@../canary.txt"), OUTSIDE)
case("confine-symlink-matrix", "rejected", "confined reads: a mass matrix symlinked to /etc/passwd",
     fe_scene(mass="@@link-passwd.mtx"), "through a symlink")
case("confine-traversal-rail", "rejected", "confined reads: a rail CSV by `../`",
     fe_scene(rail="@@../canary.txt"), OUTSIDE)
case("confine-absolute-rail", "rejected", "confined reads: a rail CSV by an absolute path",
     fe_scene(rail="@@/etc/passwd"), ABSOLUTE)
# Inside the folder but not the format: refused without quoting the content.
side_files["not-a-rail.csv"] = "root:x:0:0:root:/root:/bin/bash\n1,2\n"
side_files["not-a-record.csv"] = "root:x:0:0,root:/root:/bin/bash\nroot:x:0:0,root:/root:/bin/bash\n"
case("content-not-a-rail", "rejected", "a rail CSV that is not one is not quoted",
     fe_scene(rail="@@not-a-rail.csv"), "the header must be `node,x`")
case("content-not-a-record", "rejected", "a record CSV that is not one is not quoted",
     scene(extra="ground_motion:\n  - {file: @@not-a-record.csv, units: g}\n"),
     "the first row is not a number")

# --- forged part files for `vbi merge` (issue 23), written to
# tests/hostile/parts/: tests/it/hostile.rs merges each alone and expects exit
# 2 within the caps and no canary. (Forgeries that carry the right scene
# hash are made from a real part at test time, in tests/it/confined.rs.)
PART_SCENE = scene(extra="study:\n  type: separation_map\n  velocity_ratio: {from: 0.1, to: 0.3, count: 3}\n"
                   "  mass_ratio: {from: 0.1, to: 0.2, count: 2}\n")


def part(**fields):
    import json
    base = {"format": "vbi-part-2", "vbi_version": "0", "scenario_hash": "0000000000000000",
            "scenario_file": "scene.yaml", "scenario_source": PART_SCENE, "allow_large": False,
            "study": "separation_map", "size": 6, "shard": 1, "shards": 1, "first": 0, "end": 6,
            "wall_time": 0.0, "data_digest": "0", "data": {"study": "separation_map", "points": []}}
    base.update(fields)
    return json.dumps(base)


PARTS = {
    "huge-shards.json": part(shards=99999999999, end=0),
    "max-shards.json": part(shards=2**64 - 1, end=0),
    "allow-large.json": part(allow_large=True),
    "wrong-hash.json": part(),
    "canary-source.json": part(scenario_file="/etc/x.yaml",
                               scenario_source=scene(extra="ground_motion:\n  - {file: passwd}\n")),
    "canary-traversal.json": part(scenario_source=scene(
        extra="ground_motion:\n  - {file: ../../../../../../../../etc/passwd}\n")),
    "not-json.json": "root:x:0:0:root:/root:/bin/bash " + CANARY + "\n",
    "wrong-type.json": part(study=CANARY, shard=CANARY),
    "format-canary.json": '{"format": "' + CANARY + '"}',
}


# --- issue 23: files that passed `check` asking for unbounded work or
# holding nonsense, and refusals blamed on the wrong field.
RAIL_CAR = "  - type: rail_car\n    speed: 20.0\n"
side_files["quake-100.AT2"] = (AT2_HEAD + "NPTS=  100, DT= .0100 SEC\n"
                               + "\n".join(["0.01 0.02 0.01 0.0 -0.01"] * 20) + "\n")
side_files["quake-dt-1e-8.AT2"] = AT2_HEAD + "NPTS=    4, DT= .00000001 SEC\n0.1 0.2 0.1 0.0\n"
side_files["quake-gap.csv"] = ("time [s], acceleration [g]\n0, 0\n0.01, 0.1\n"
                               "0.0100000001, 0.1\n0.02, 0\n")
case("size-ground-repeated", "budget",
     "one record listed 20 times counts 20 times against `limits.ground_points` (lowered "
     "to 1000 here: 100 samples each, the 11th is refused)",
     scene(extra="ground_motion:\n" + "  - {file: quake-100.AT2}\n" * 10
           + "  - {file: @@quake-100.AT2}\n" + "  - {file: quake-100.AT2}\n" * 9
           + "limits: {ground_points: 1000}\n"), "limits.ground_points")
case("tr-car-spacing-1e308", "rejected",
     "a train's car spacing of 1e308 m (was blamed on the speed: \"over the inf s run\")",
     scene(vehicles="  - {type: train, count: 3, car_spacing: @@1e308, speed: 20.0}\n"),
     "a car spacing of 1e308 m")
case("tr-axle-spacing-1e308", "rejected",
     "a moving force's axle spacing of 1e308 m, blamed at the spacing",
     scene(vehicles="  - {type: moving_force, loads: [1e5, 1e5], axle_spacings: [@@1e308], speed: 20.0}\n"),
     "an axle spacing of 1e308 m")
case("tr-axle-position-1e4", "rejected",
     "axle positions 10 km apart, blamed at the far axle's position",
     scene(vehicles="  - {type: moving_force, loads: [1e5, 1e5], axle_positions: [0, @@1e4], speed: 20.0}\n"),
     "an axle spacing of 10000 m")
case("tr-speed-1e-4", "rejected",
     "a speed of 0.1 mm/s (a 20 m crossing of 55 hours), below any creep test",
     scene(vehicles="  - {type: moving_force, loads: [1e5], speed: @@1e-4}\n"),
     "a speed of 1e-4 m/s")
case("tr-free-vibration-1e7", "rejected",
     "a free vibration of 1e7 s (116 days) after the crossing",
     scene(extra="solver: {free_vibration: @@1e7}\n"),
     "a free-vibration time of 1e7 s")
case("plausible-inertia-1e308", "rejected", "a rail car's pitch inertia of 1e308 kg·m²",
     scene(vehicles=RAIL_CAR + "    parameters: {body_pitch_inertia: @@1.0e308}\n"),
     "moment of inertia")
case("plausible-truck-inertia-1e308", "rejected", "a truck's roll inertia of 1e308 kg·m²",
     scene(vehicles="  - type: h20_44\n    speed: 20.0\n    parameters: {body_roll_inertia: @@1.0e308}\n"),
     "moment of inertia")
case("plausible-polar-mass-1e308", "rejected", "a 3D beam's polar mass of 1e308 kg·m²/m",
     scene(bridge=BEAM + "  lateral_bending_stiffness: 1.0e10\n  torsional_stiffness: 1.0e9\n"
           "  polar_mass: @@1.0e308\n"), "polar mass")
case("geometry-bogies-overlap", "rejected",
     "a rail car whose bogie half-spacing (1 m) is below its half wheelbase (1.25 m)",
     scene(vehicles=RAIL_CAR + "    parameters: {half_bogie_spacing: @@1.0}\n"), "overlap")
case("geometry-half-wheelbase-0", "rejected",
     "half_wheelbase 0 passed `check` and failed `run` with no static equilibrium",
     scene(vehicles=RAIL_CAR + "    parameters: {half_wheelbase: @@0}\n"),
     "half_wheelbase must be positive")
case("ok-tab-after-colon", "accepted", "a tab after `:` is valid YAML separation",
     scene(vehicles=OSC.replace("speed: 27.7", "speed:\t27.7")
           .replace("sprung_mass: ", "sprung_mass:\t")))
case("steps-ground-interval", "rejected",
     "an AT2 interval of 1e-8 s (it would set the time step) is refused as no accelerograph's, at the record",
     scene(extra="ground_motion:\n  - {file: @@quake-dt-1e-8.AT2}\n"),
     "outside the plausible sampling interval")
case("steps-ground-gap", "rejected",
     "two samples 1e-10 s apart in a CSV record are refused as no accelerograph's, at the record",
     scene(extra="ground_motion:\n  - {file: @@quake-gap.csv}\n"), "outside the plausible sampling interval")
case("steps-ground-start-time", "budget",
     "a start time of 1e16 s leaves the samples no digits (a zero interval): blamed at it",
     scene(extra="ground_motion:\n  - {file: quake-ok.csv, start_time: @@1.0e16}\n"),
     "start the record within the run")
case("steps-car-spacing", "budget",
     "40 cars 900 m apart (a 36 km train) make the run long: blamed at `car_spacing`, not the "
     "speed (each spacing is within the plausible range; 1e7 m is refused as a spacing: "
     "steps-car-spacing-1e7)",
     scene(vehicles="  - {type: train, speed: 2, count: 40, car_spacing: @@900}\n"),
     "shorten it")
case("steps-car-spacing-1e7", "rejected",
     "cars 10,000 km apart: a car spacing outside the plausible range, at the spacing",
     scene(vehicles="  - {type: train, speed: 20, count: 3, car_spacing: @@1.0e7}\n"),
     "a car spacing of 1e7 m")

# Issue 39.5: a YAML tag whose node starts on the next line (a block
# collection) was located a line off; the tag itself is blamed.
case("syntax-tag-block-mapping", "rejected", "a tag on a mapping value whose block mapping starts the next line",
     scene(bridge=BEAM.replace("bridge:\n", "bridge: @@!custom\n")), "tags are not supported")
case("syntax-tag-block-sequence", "rejected", "a tag on a block sequence starting the next line",
     scene(extra="record: @@!custom\n  - {name: m, quantity: bridge_displacement, x: 12.5}\n"),
     "tags are not supported")
case("syntax-tag-sequence-item", "rejected", "a python object tag on a sequence item whose mapping starts the next line",
     scene(vehicles="  - @@!!python/object:os.system\n" + OSC.replace("  - type", "    type")),
     "tags are not supported")
case("syntax-tag-key", "rejected", "a tag on a key",
     scene(bridge=BEAM.replace("  spans:", "  @@!custom spans:")), "tags are not supported")
case("syntax-tag-comment-anchor", "rejected", "a tag after an anchor, with a comment and a blank line before the mapping",
     scene(bridge=BEAM.replace("bridge:\n", "bridge: &b @@!custom  # note\n\n")), "tags are not supported")
case("syntax-tag-document", "rejected", "a tag on the document's root mapping",
     "@@!custom\n" + scene(), "tags are not supported")
# Issue 39.5: surfaces of metres ran (a harmonic of 10 km: mid-span −4,758 m).
for slug, surface, message in [
    ("harmonic-amplitude-10km", "{type: harmonic, amplitude: @@10 km, wavelength: 5}", "physically plausible range 0 to 0.5 m"),
    ("harmonic-lateral-amplitude", "{type: harmonic, amplitude: @@0.6, wavelength: 5, direction: lateral}", "alignment amplitude"),
    ("harmonic-wavelength-20km", "{type: harmonic, amplitude: 0.001, wavelength: @@20 km}", "0.001 to 10000 m"),
    ("bump-height-2m", "{type: bump, start: 2, length: 1, height: @@2}", "a bump height of 2 m"),
    ("bump-length-20km", "{type: bump, start: 2, length: @@2.0e4, height: 0.01}", "a bump length"),
    ("dip-depth-1e300", "{type: dip, start: 2, length: 1, depth: @@1e300}", "a dip depth"),
    ("ramp-rise-minus-3m", "{type: ramp, start: 2, length: 1, height: @@-3}", "-0.5 to 0.5 m"),
    ("step-height-1e308", "{type: step, position: 2, height: @@1e308}", "a step's height"),
    ("piecewise-point-2m", "{type: piecewise_linear, points: [[0, 0], @@[5, 2], [8, 0]]}", "point 2's elevation"),
    ("random-coefficient-15", "{type: random, coefficient: @@15, seed: 1}", "roughness coefficient"),
    ("random-sampling-20km", "{type: random, class: good, sampling_length: @@2.0e4, terms: 100}", "a sampling length"),
    ("german-band-50km", "{type: german, interference: low, longest_wavelength: @@5.0e4}", "a longest wavelength"),
    ("fra-run-in-20km", "{type: fra, class: 5, run_in: @@2.0e4}", "a run-in"),
    ("measured-metres", "{type: measured, file: @@profile-metres.csv}", "profile-metres.csv:4: column 2"),
    ("measured-lateral-metres", "{type: measured, file: @@profile-lateral.csv}", "profile-lateral.csv:3: column 4"),
]:
    case("plausible-surface-" + slug, "rejected", "a surface of metres: " + slug.replace("-", " "),
         scene(extra="surface: " + surface + "\n"), message)
# Issue 39.5: 125 rail cars passed `check` and ran for hours: the run's
# work (steps × wheels × (modes + contact system)) is budgeted at the count.
case("size-run-work-125-cars", "budget", "a train of 125 rail cars (500 wheels over 375,000 steps)",
     scene(vehicles="  - {type: train, speed: 30, count: @@125, car_spacing: 25}\n",
           extra="record: [{name: m, quantity: bridge_displacement, x: 12.5}]\n"),
     "limits.run_work")
side_files["profile-metres.csv"] = "x,elevation\n-50,0\n0,0.001\n10,3.0\n200,0\n"
side_files["profile-lateral.csv"] = ("x,left,right,left_lateral,right_lateral\n-50,0,0,0,0\n"
                                     "10,0,0,700,0\n200,0,0,0,0\n")


def locate(text):
    """Removes the `@@` marker; returns (text, line, col) of the marker."""
    is_bytes = isinstance(text, bytes)
    marker = b"@@" if is_bytes else "@@"
    at = text.find(marker)
    if at < 0:
        return text, None, None
    before = text[:at]
    if is_bytes:
        before = before.decode("utf-8", "replace")
    # Line breaks as YAML counts them: \n, \r\n, lone \r.
    lines = before.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    line = len(lines)
    col = len(lines[-1]) + 1
    if line == 1 and lines[0].startswith("\ufeff"):
        col -= 1
    return text[:at] + text[at + 2:], line, col


# --- issue 39.3: control characters a YAML escape writes into a unit, a
# variant, a key, a DOF name or a data-file name are shown escaped
# (`\u{1b}`), never raw: every case's output is also checked for raw
# control characters by tests/it/hostile.rs.
case("esc-unit", "rejected", "ESC inside a unit is shown escaped",
     scene(bridge=BEAM.replace("mass_per_length: 2303.0", 'mass_per_length: @@"2303 kg/m\\e[31mRED"')),
     "\\u{1b}[31mRED")
case("esc-variant", "rejected", "ESC inside a variant name is shown escaped",
     scene(bridge=BEAM.replace("type: beam", 'type: @@"be\\e[2Jam"')), "\\u{1b}[2J")
case("esc-key", "rejected", "NUL and ESC inside an unknown key are shown escaped",
     scene(bridge=BEAM + '  @@"sp\\0an\\e[2J": 1\n'), "\\0an\\u{1b}[2J")
case("esc-dof", "rejected", "ESC inside a DOF name is shown escaped",
     scene(extra='record:\n  - {name: d, quantity: vehicle_displacement, vehicle: 1, dof: @@"spr\\e[2Jung"}\n'),
     "\\u{1b}[2J")
case("esc-data-file", "rejected", "ESC inside a data-file name is shown escaped",
     scene(extra='surface: {type: measured, file: @@"p\\e[2J.csv"}\n'), "\\u{1b}[2J")
case("esc-bell-name", "rejected", "BEL and CR inside a record name are refused where written",
     scene(extra='record:\n  - {name: @@"a\\a\\rb", quantity: bridge_displacemnt, x: 12.5}\n'),
     "control character U+0007")

def main():
    if os.path.isdir(CASES):
        shutil.rmtree(CASES)
    os.makedirs(CASES)
    os.makedirs(FE, exist_ok=True)
    with open(os.path.join(HERE, "canary.txt"), "w", encoding="utf-8") as f:
        f.write(CANARY_TEXT)
    for name, target in SYMLINKS.items():
        os.symlink(target, os.path.join(CASES, name))
    parts = os.path.join(HERE, "parts")
    if os.path.isdir(parts):
        shutil.rmtree(parts)
    os.makedirs(parts)
    for name, text in PARTS.items():
        with open(os.path.join(parts, name), "w", encoding="utf-8") as f:
            f.write(text)
    for name, text in FE_FILES.items():
        with open(os.path.join(FE, name), "w", encoding="utf-8") as f:
            f.write(text)
    names = set()
    rows = ["# file\toutcome\tline:col\tmessage\twhat it tests"]
    for file, outcome, what, text, message in cases:
        assert file not in names, file
        names.add(file)
        body, line, col = locate(text)
        data = body if isinstance(body, bytes) else body.encode("utf-8")
        with open(os.path.join(CASES, file + ".yaml"), "wb") as f:
            f.write(data)
        # A rejected case without a marker (an unclosed bracket: the
        # scanner notices it at the end) only needs some FILE:LINE:COL.
        where = f"{line}:{col}" if line is not None else "-"
        rows.append("\t".join([file + ".yaml", outcome, where, message, what]))
    for file, text in side_files.items():
        with open(os.path.join(CASES, file), "w", encoding="utf-8") as f:
            f.write(text)
    with open(os.path.join(HERE, "expected.tsv"), "w", encoding="utf-8") as f:
        f.write("\n".join(rows) + "\n")
    print(f"{len(cases)} cases written to {CASES}")


if __name__ == "__main__":
    main()
