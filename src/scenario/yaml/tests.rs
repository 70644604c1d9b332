//! Unit tests of the parent module.

use super::*;
use serde_json::json;

fn at(line: usize, col: usize) -> Location {
    Location { line, col }
}

fn doc(src: &str) -> Node {
    parse(src).expect("valid YAML").expect("non-empty document")
}

fn syntax_err(src: &str) -> SyntaxError {
    parse(src).expect_err("expected a syntax error")
}

#[test]
fn locations_are_one_based() {
    let n = doc("name: demo\nbridge:\n  type: beam\n  spans: [20.0, 30]\n");
    assert_eq!(n.loc, at(1, 1));
    assert_eq!(n.key_loc("bridge"), Some(at(2, 1)));
    let bridge = n.get("bridge").unwrap();
    assert_eq!(bridge.loc, at(3, 3));
    assert_eq!(bridge.key_loc("spans"), Some(at(4, 3)));
    let spans = bridge.get("spans").unwrap();
    assert_eq!(spans.loc, at(4, 10));
    let NodeKind::Sequence(items) = &spans.kind else {
        panic!("not a sequence")
    };
    assert_eq!(items[1].loc, at(4, 17));
    assert_eq!(n.get("name").unwrap().loc, at(1, 7));
}

#[test]
fn columns_count_chars_and_crlf_is_one_break() {
    let n = doc("a: 1\r\nbé: ü\r\nc: 3");
    assert_eq!(n.key_loc("bé"), Some(at(2, 1)));
    assert_eq!(n.get("bé").unwrap().loc, at(2, 5));
    assert_eq!(n.get("c").unwrap().loc, at(3, 4));
}

#[test]
fn scalar_kinds() {
    let n = doc("a: ~\nb: null\nc: NULL\nd:\ne: 'x'\nf: \"1\"\ng: |\n  text\nh: 12\n");
    for k in ["a", "b", "c", "d"] {
        assert_eq!(n.get(k).unwrap().kind, NodeKind::Null, "key {k}");
    }
    let scalar = |k: &str| n.get(k).unwrap().kind.clone();
    assert_eq!(
        scalar("e"),
        NodeKind::Scalar {
            text: "x".into(),
            plain: false
        }
    );
    assert_eq!(
        scalar("f"),
        NodeKind::Scalar {
            text: "1".into(),
            plain: false
        }
    );
    assert_eq!(
        scalar("g"),
        NodeKind::Scalar {
            text: "text\n".into(),
            plain: false
        }
    );
    assert_eq!(
        scalar("h"),
        NodeKind::Scalar {
            text: "12".into(),
            plain: true
        }
    );
}

#[test]
fn empty_documents_are_none() {
    for src in [
        "",
        "   \n\n",
        "# only a comment\n",
        "---\n",
        "--- # c\n...\n",
    ] {
        assert_eq!(parse(src).unwrap(), None, "{src:?}");
    }
    assert_eq!(parse("~").unwrap().unwrap().kind, NodeKind::Null);
}

#[test]
fn aliases_clone_the_anchored_node() {
    let n = doc("base: &b {type: beam, spans: [1]}\ncopy: *b\nk: &s hello\nl: *s\n");
    let base = n.get("base").unwrap();
    let copy = n.get("copy").unwrap();
    assert_eq!(copy.kind, base.kind);
    assert_eq!(copy.loc, at(2, 7));
    assert_eq!(n.get("l").unwrap().as_str(), Some("hello"));
    assert_eq!(n.get("l").unwrap().loc, at(4, 4));
}

#[test]
fn only_one_document() {
    let e = syntax_err("a: 1\n---\nb: 2\n");
    assert_eq!(e.loc, at(2, 1));
    assert_eq!(e.message, "only one YAML document per file is allowed");
}

#[test]
fn duplicate_keys() {
    let e = syntax_err("a: 1\nb:\n  x: 1\n  y: 2\n  x: 3\n");
    assert_eq!(e.loc, at(5, 3));
    assert_eq!(e.message, "duplicate key `x` (first defined at line 3)");
    let e = syntax_err("{a: 1, 'a': 2}");
    assert_eq!(
        (e.loc, e.message.as_str()),
        (at(1, 8), "duplicate key `a` (first defined at line 1)")
    );
    // The same key in different mappings is fine.
    doc("- x: 1\n- x: 2\n");
}

#[test]
fn unsupported_features() {
    let e = syntax_err("a: 1\n? [x]\n: 2\n");
    assert_eq!(e.loc, at(2, 3));
    assert!(e.message.contains("keys must be scalars"), "{}", e.message);
    // The tag itself is blamed, not the node after it (issue 10: a custom
    // tag was reported past the tag).
    let e = syntax_err("a: !foo x\n");
    assert_eq!(
        (e.loc, e.message.as_str()),
        (at(1, 4), "YAML tags are not supported")
    );
    assert_eq!(syntax_err("a:\n  b: !!str [1]\n").loc, at(2, 6));
    // A block collection's tag ends its line: the node starts on the next
    // (issue 39: `syn-tag-custom` was a line off).
    assert_eq!(syntax_err("a: !foo\n  b: 1\n").loc, at(1, 4));
    assert_eq!(syntax_err("- !foo # c\n\n  b: 1\n").loc, at(1, 3));
    assert_eq!(syntax_err("a: !foo\n  - 1\n").loc, at(1, 4));
    let e = syntax_err("a: !!str 1\n");
    assert_eq!(e.message, "YAML tags are not supported");
    let e = syntax_err("- !!map {a: 1}\n");
    assert_eq!(e.message, "YAML tags are not supported");
    let e = syntax_err("base: &b {x: 1}\nc:\n  <<: *b\n");
    assert_eq!(
        (e.loc, e.message.as_str()),
        (at(3, 3), "merge keys (`<<`) are not supported")
    );
    // A quoted `<<` is an ordinary key.
    assert!(doc("'<<': 1").get("<<").is_some());
}

#[test]
fn scanner_errors_are_located() {
    let e = syntax_err("a: [1, 2\nb: 3\n");
    let want = "YAML syntax error: illegal placement of ':' indicator \
                    (inside the `[` opened at line 1, column 4)";
    assert_eq!((e.loc, e.message.as_str()), (at(2, 2), want));
    let e = syntax_err("a: [1, 2\n");
    let want = "YAML syntax error: while parsing a flow sequence, expected ',' or ']' \
                    (inside the `[` opened at line 1, column 4)";
    assert_eq!((e.loc, e.message.as_str()), (at(2, 1), want));
    let e = syntax_err("a: b: c\n");
    assert_eq!(e.loc, at(1, 5));
    assert_eq!(
        e.message,
        "YAML syntax error: mapping values are not allowed in this context"
    );
    let e = syntax_err("a: *nope\n");
    assert_eq!(e.loc, at(1, 4));
    let e = syntax_err("- &a [*a]\n");
    assert!(e.message.contains("recursive alias"), "{}", e.message);
}

#[test]
fn nesting_and_alias_bombs_are_bounded() {
    let deep = format!("{}x", "- ".repeat(10_000));
    let e = syntax_err(&deep);
    assert!(e.message.contains("nesting deeper"), "{}", e.message);
    // saphyr has its own (smaller) limit for flow collections.
    let e = syntax_err(&"[".repeat(10_000));
    assert!(e.message.contains("recursion limit"), "{}", e.message);
    let mut chain = String::from("a0: &a0 [0]\n");
    for i in 1..200 {
        chain.push_str(&format!("a{i}: &a{i} [*a{}]\n", i - 1));
    }
    assert!(syntax_err(&chain).message.contains("nesting deeper"));
    let mut bomb = String::from("a: &a [x, x, x, x, x, x, x, x, x, x]\n");
    for c in 'b'..='j' {
        let prev = (c as u8 - 1) as char;
        bomb.push_str(&format!("{c}: &{c} [*{prev}, *{prev}, *{prev}, *{prev}, *{prev}, *{prev}, *{prev}, *{prev}, *{prev}, *{prev}]\n"));
    }
    assert!(syntax_err(&bomb).message.contains("more than"));
}

#[test]
fn locate_paths() {
    let n = doc("bridge:\n  type: beam\n  spans: [1, 2]\nvehicles:\n  - speed: 3\n");
    use PathSeg::{Index, Key};
    assert_eq!(n.locate(&[]), at(1, 1));
    assert_eq!(
        n.locate(&[Key("bridge"), Key("spans"), Index(1)]),
        at(3, 14)
    );
    assert_eq!(
        n.locate(&[Key("vehicles"), Index(0), Key("speed")]),
        at(5, 12)
    );
    // Missing final key: the enclosing mapping.
    assert_eq!(
        n.locate(&[Key("vehicles"), Index(0), Key("mass")]),
        at(5, 5)
    );
    // Missing index and wrong kinds stop where the path breaks.
    assert_eq!(n.locate(&[Key("vehicles"), Index(7), Key("x")]), at(5, 3));
    assert_eq!(n.locate(&[Key("bridge"), Index(0)]), at(2, 3));
    assert_eq!(n.get("nope"), None);
    assert_eq!(n.key_loc("nope"), None);
}

#[test]
fn core_schema_resolution() {
    let cases: &[(&str, Resolved)] = &[
        ("12", Resolved::Int(12)),
        ("-3", Resolved::Int(-3)),
        ("+1", Resolved::Int(1)),
        ("007", Resolved::Int(7)),
        ("0x1F", Resolved::Int(31)),
        ("0o17", Resolved::Int(15)),
        ("1.5", Resolved::Float(1.5)),
        ("1e5", Resolved::Float(1e5)),
        ("1.0e-4", Resolved::Float(1e-4)),
        (".5", Resolved::Float(0.5)),
        ("-.5E+1", Resolved::Float(-5.0)),
        ("2.", Resolved::Float(2.0)),
        (".inf", Resolved::Float(f64::INFINITY)),
        ("-.Inf", Resolved::Float(f64::NEG_INFINITY)),
        ("True", Resolved::Bool(true)),
        ("FALSE", Resolved::Bool(false)),
        ("Null", Resolved::Null),
        (
            "99999999999999999999999999999999999999999",
            Resolved::IntOverflow,
        ),
        ("yes", Resolved::Str("yes")),
        ("0x", Resolved::Str("0x")),
        ("0x+1", Resolved::Str("0x+1")),
        ("-0x1", Resolved::Str("-0x1")),
        ("1e", Resolved::Str("1e")),
        (".", Resolved::Str(".")),
        ("inf", Resolved::Str("inf")),
        ("nan", Resolved::Str("nan")),
        ("1_000", Resolved::Str("1_000")),
        ("tRUE", Resolved::Str("tRUE")),
        ("-", Resolved::Str("-")),
    ];
    for (text, want) in cases {
        assert_eq!(resolve_plain(text), *want, "{text}");
    }
    assert!(matches!(resolve_plain(".NaN"), Resolved::Float(f) if f.is_nan()));
}

#[test]
fn to_json_uses_core_schema() {
    let n = doc(concat!(
        "a: [1, -2, 0x10, 1.5, 1e3, .inf, -.inf, .nan, 1e400]\n",
        "b: {t: true, f: False, n: ~, e: , s: '12', p: hello, big: 18446744073709551615}\n",
        "c: 99999999999999999999999\n",
    ));
    let want = json!({
        "a": [1, -2, 16, 1.5, 1000.0, ".inf", "-.inf", ".nan", "1e400"],
        "b": {"t": true, "f": false, "n": null, "e": null, "s": "12", "p": "hello",
              "big": 18446744073709551615u64},
        "c": 1e23,
    });
    assert_eq!(n.to_json(), want);
}

/// Tiny deterministic PRNG so the fuzz tests need no extra dependency.
fn lcg(state: &mut u64) -> u64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    *state >> 33
}

#[test]
fn fuzz_random_bytes_never_panic() {
    let alphabet = b"ab:-[]{},&*!|>'\"#?~ \n\t\r.0123456789e%<@`";
    let mut state = 42;
    for _ in 0..3000 {
        let len = (lcg(&mut state) % 60) as usize;
        let bytes: Vec<u8> = (0..len)
            .map(|_| {
                let r = lcg(&mut state) as usize;
                if r.is_multiple_of(10) {
                    (r >> 8) as u8
                } else {
                    alphabet[(r >> 8) % alphabet.len()]
                }
            })
            .collect();
        let text = String::from_utf8_lossy(&bytes);
        if let Ok(Some(n)) = parse(&text) {
            let _ = n.to_json();
        }
    }
}

#[test]
fn fuzz_truncated_documents_never_panic() {
    let src = "name: \"démo\"\nbridge: &b\n  type: beam # comment\n  spans: [20.0, {a: 1}]\n\
                   vehicles:\n  - type: oscillator\n    speed: |\n      x\n  - *b\n...\n";
    for (i, _) in src.char_indices() {
        let _ = parse(&src[..i]);
        let _ = parse(&src[i..]);
    }
}

/// Issue 10: mistakes saphyr notices one line late are blamed on their line.
#[test]
fn late_scanner_errors_are_moved_to_their_cause() {
    // A key without a colon.
    let e = syntax_err("name: x\nbridge:\n  type: beam\n  spans [25.0]\n  mass: 1\n");
    assert_eq!(e.loc, at(4, 3), "{}", e.message);
    assert!(e.message.contains("no `:`"), "{}", e.message);
    // A colon without a space.
    let e = syntax_err("name: x\nbridge:\n  type: beam\n  spans:[25.0]\n  mass: 1\n");
    assert_eq!(e.loc, at(4, 3), "{}", e.message);
    assert!(e.message.contains("space after it"), "{}", e.message);
    // A tab-indented line after a plain scalar.
    let e = syntax_err("name: x\nbridge:\n  type: beam\n\tspans: [25.0]\n");
    assert_eq!(e.loc, at(4, 1), "{}", e.message);
    assert!(e.message.contains("tabs"), "{}", e.message);
}
