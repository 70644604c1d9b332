//! The tree built from saphyr's events: nesting and alias expansion
//! bounded, duplicate keys refused, every node located.

use std::collections::HashMap;

use saphyr_parser::{Event, Span};

use super::*;

/// A finished node plus the bookkeeping needed to bound alias expansion.
#[derive(Clone)]
pub(super) struct Built {
    pub(super) node: Node,
    height: usize,
    size: usize,
}

enum Content {
    Seq(Vec<Node>),
    Map {
        entries: Vec<(Node, Node)>,
        key: Option<Node>,
        /// key text -> where it was first defined, for duplicate detection.
        seen: HashMap<String, Location>,
    },
}

pub(super) struct Frame {
    loc: Location,
    anchor: usize,
    /// Flow collections (`[`/`{`) get a hint on syntax errors: unclosed brackets
    /// are reported by saphyr at EOF, far away from the bracket.
    flow: bool,
    height: usize,
    size: usize,
    content: Content,
}

pub(super) struct Builder<'s> {
    pub(super) source: &'s str,
    pub(super) stack: Vec<Frame>,
    pub(super) anchors: HashMap<usize, Built>,
    pub(super) root: Option<Built>,
    pub(super) nodes: usize,
    pub(super) documents: usize,
}

pub(super) fn err(loc: Location, message: impl Into<String>) -> SyntaxError {
    SyntaxError {
        loc,
        message: message.into(),
    }
}

impl Builder<'_> {
    fn open(&mut self, span: &Span, anchor: usize, content: Content) -> Result<(), SyntaxError> {
        let loc = Location::from_marker(&span.start);
        if self.stack.len() >= MAX_DEPTH {
            return Err(err(
                loc,
                format!("nesting deeper than {MAX_DEPTH} levels is not supported"),
            ));
        }
        let flow = span.end.index() > span.start.index();
        self.stack.push(Frame {
            loc,
            anchor,
            flow,
            height: 0,
            size: 0,
            content,
        });
        Ok(())
    }

    fn close(&mut self) -> Result<(), SyntaxError> {
        let Some(frame) = self.stack.pop() else {
            return Ok(());
        };
        let kind = match frame.content {
            Content::Seq(items) => NodeKind::Sequence(items),
            Content::Map { entries, .. } => NodeKind::Mapping(entries),
        };
        let node = Node {
            kind,
            loc: frame.loc,
        };
        let built = Built {
            node,
            height: frame.height + 1,
            size: frame.size + 1,
        };
        self.finish(built, frame.anchor)
    }

    /// Register a completed node: remember its anchor and attach it to its parent.
    fn finish(&mut self, built: Built, anchor: usize) -> Result<(), SyntaxError> {
        self.nodes += 1;
        if anchor > 0 {
            self.anchors.insert(anchor, built.clone());
        }
        self.attach(built)
    }

    fn alias(&mut self, span: &Span, id: usize) -> Result<(), SyntaxError> {
        let loc = Location::from_marker(&span.start);
        let Some(target) = self.anchors.get(&id) else {
            return Err(err(
                loc,
                "alias refers to an anchor whose node is not complete yet (recursive alias)",
            ));
        };
        if self.stack.len() + target.height > MAX_DEPTH {
            return Err(err(
                loc,
                format!("alias expands to nesting deeper than {MAX_DEPTH} levels"),
            ));
        }
        self.nodes += target.size;
        if self.nodes > MAX_NODES {
            return Err(err(
                loc,
                format!("aliases expand to more than {MAX_NODES} nodes"),
            ));
        }
        let mut built = target.clone();
        built.node.loc = loc;
        self.attach(built)
    }

    fn attach(&mut self, built: Built) -> Result<(), SyntaxError> {
        let Some(frame) = self.stack.last_mut() else {
            self.root = Some(built);
            return Ok(());
        };
        frame.height = frame.height.max(built.height);
        frame.size += built.size;
        match &mut frame.content {
            Content::Seq(items) => items.push(built.node),
            Content::Map { entries, key, seen } => match key.take() {
                Some(k) => entries.push((k, built.node)),
                None => {
                    let k = built.node;
                    let text = match &k.kind {
                        NodeKind::Null => "null",
                        NodeKind::Scalar { text, plain } => {
                            if *plain && text == "<<" {
                                return Err(err(k.loc, "merge keys (`<<`) are not supported"));
                            }
                            text.as_str()
                        }
                        NodeKind::Sequence(_) | NodeKind::Mapping(_) | NodeKind::Placeholder => {
                            return Err(err(
                                k.loc,
                                "mapping keys must be scalars, not sequences or mappings",
                            ));
                        }
                    };
                    if let Some(first) = seen.get(text) {
                        let msg = format!(
                            "duplicate key `{text}` (first defined at line {})",
                            first.line
                        );
                        return Err(err(k.loc, msg));
                    }
                    seen.insert(text.to_owned(), k.loc);
                    *key = Some(k);
                }
            },
        }
        Ok(())
    }

    pub(super) fn event(&mut self, ev: Event<'_>, span: &Span) -> Result<(), SyntaxError> {
        let loc = Location::from_marker(&span.start);
        let tagged = matches!(
            &ev,
            Event::Scalar(_, _, _, Some(_))
                | Event::SequenceStart(_, Some(_))
                | Event::MappingStart(_, Some(_))
        );
        if tagged {
            // saphyr marks the node after its tag; point at the tag itself.
            return Err(err(
                tag_start(self.source, loc),
                "YAML tags are not supported",
            ));
        }
        match ev {
            Event::DocumentStart(_) => {
                self.documents += 1;
                if self.documents > 1 {
                    return Err(err(loc, "only one YAML document per file is allowed"));
                }
            }
            Event::Scalar(text, style, anchor, _) => {
                let plain = style == ScalarStyle::Plain;
                let implicit_null = text == "~";
                let kind = if plain && matches!(resolve_plain(&text), Resolved::Null) {
                    NodeKind::Null
                } else {
                    NodeKind::Scalar {
                        text: text.into_owned(),
                        plain,
                    }
                };
                let built = Built {
                    node: Node { kind, loc },
                    height: 1,
                    size: 1,
                };
                // A document that is only `---` (or `---` `...`) yields an
                // implicit `~` that is not in the source: treat it like an empty file.
                let empty_root = self.stack.is_empty()
                    && plain
                    && implicit_null
                    && (span.start.index() == span.end.index()
                        || self.source.chars().nth(span.start.index()) != Some('~'));
                if !empty_root {
                    self.finish(built, anchor)?;
                }
            }
            Event::Alias(id) => self.alias(span, id)?,
            Event::SequenceStart(anchor, _) => self.open(span, anchor, Content::Seq(Vec::new()))?,
            Event::MappingStart(anchor, _) => {
                let content = Content::Map {
                    entries: Vec::new(),
                    key: None,
                    seen: HashMap::new(),
                };
                self.open(span, anchor, content)?
            }
            Event::SequenceEnd | Event::MappingEnd => self.close()?,
            Event::Nothing | Event::StreamStart | Event::StreamEnd | Event::DocumentEnd => {}
        }
        Ok(())
    }

    /// Add the innermost open flow collection to a scanner error: saphyr
    /// reports an unclosed `[` at the end of the file, not at the bracket.
    pub(super) fn scan_error_message(&self, info: &str) -> String {
        let mut msg = format!("YAML syntax error: {info}");
        if let Some(frame) = self.stack.iter().rev().find(|f| f.flow) {
            let bracket = if matches!(frame.content, Content::Seq(_)) {
                '['
            } else {
                '{'
            };
            msg.push_str(&format!(
                " (inside the `{bracket}` opened at line {}, column {})",
                frame.loc.line, frame.loc.col
            ));
        }
        msg
    }
}
