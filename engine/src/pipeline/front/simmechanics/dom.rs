//! A compact, read-only element tree over the input bytes.
//!
//! quick-xml's borrowed event stream is turned into one `Vec` of fixed-size nodes that refer to
//! the input by byte offsets: no per-element allocation, and the lowering can then look children
//! up by name (never by position) and describe any element's ancestry in an error message.
//! Text is kept raw (entities are decoded only when a string is extracted).

use quick_xml::events::attributes::Attributes;
use quick_xml::events::Event;
use quick_xml::Reader;

/// Index of a node in [`Doc::nodes`].
pub(crate) type NodeId = u32;

/// Marks "no node" in the links below.
const NONE: u32 = u32::MAX;

/// Most elements read (32 bytes each: 128 MiB of tree). A real export has a few hundred
/// thousand; a file of millions of tiny elements is refused before the tree outgrows memory.
pub(crate) const MAX_ELEMENTS: usize = 4_000_000;
/// Deepest element nesting (real exports nest about 15 deep).
pub(crate) const MAX_NESTING: usize = 256;

/// One element. Offsets are into [`Doc::bytes`].
#[derive(Clone, Copy, Debug)]
struct Node {
    /// Offset of the `<` of the start tag.
    start: u32,
    /// The name is `start + 1 .. name_end`.
    name_end: u32,
    /// The attributes are `name_end .. attrs_end`.
    attrs_end: u32,
    /// Raw character data directly inside the element: from the start of its first text chunk
    /// to the end of its last one (empty when there is none).
    text_start: u32,
    text_end: u32,
    parent: u32,
    first_child: u32,
    next_sibling: u32,
}

/// The element tree of one document. Node 0 is the root element.
pub(crate) struct Doc<'a> {
    pub bytes: &'a [u8],
    nodes: Vec<Node>,
}

/// A syntax error found while building the tree: where, what, and the tree read so far (to
/// describe the innermost open element).
pub(crate) struct BuildError<'a> {
    pub offset: usize,
    pub message: String,
    pub doc: Doc<'a>,
    pub open: Option<NodeId>,
}

/// Outcome of looking at a document's first element.
pub(crate) enum Root<'a> {
    Element {
        name: &'a [u8],
        offset: usize,
    },
    /// No element at all (empty or only a prolog).
    Missing,
    /// Malformed before the root element.
    Error {
        offset: usize,
        message: String,
    },
}

/// Finds the root element's name without reading further than its start tag.
pub(crate) fn root_element(bytes: &[u8]) -> Root<'_> {
    let mut reader = Reader::from_reader(bytes);
    loop {
        let before = pos(&reader);
        match reader.read_event() {
            Ok(Event::Start(e)) | Ok(Event::Empty(e)) => {
                let end = before + 1 + e.name().as_ref().len();
                return match bytes.get(before + 1..end) {
                    Some(name) => Root::Element { name, offset: before },
                    None => Root::Error { offset: before, message: "bad start tag".into() },
                };
            }
            Ok(Event::Eof) => return Root::Missing,
            Ok(Event::End(_)) => return Root::Error { offset: before, message: "end tag before any start tag".into() },
            Ok(_) => {}
            Err(e) => return Root::Error { offset: reader.error_position() as usize, message: e.to_string() },
        }
    }
}

fn pos<R>(reader: &Reader<R>) -> usize {
    reader.buffer_position() as usize
}

impl<'a> Doc<'a> {
    /// Reads the whole document. `bytes.len()` must fit in `u32` (the caller checks).
    pub fn build(bytes: &'a [u8]) -> Result<Doc<'a>, Box<BuildError<'a>>> {
        let mut doc = Doc { bytes, nodes: Vec::with_capacity((bytes.len() / 48 + 16).min(MAX_ELEMENTS)) };
        let mut reader = Reader::from_reader(bytes);
        // (node, last child so far) of every open element, innermost last.
        let mut stack: Vec<(u32, u32)> = Vec::with_capacity(32);
        let mut root_done = false;
        let fail = |doc: Doc<'a>, stack: &[(u32, u32)], offset: usize, message: String| {
            let open = stack.last().map(|&(n, _)| n);
            Err(Box::new(BuildError { offset, message, doc, open }))
        };
        loop {
            let before = pos(&reader);
            let event = match reader.read_event() {
                Ok(e) => e,
                Err(e) => {
                    let offset = reader.error_position() as usize;
                    return fail(doc, &stack, offset, e.to_string());
                }
            };
            let after = pos(&reader);
            let (empty, name_len) = match &event {
                Event::Start(e) => (false, e.name().as_ref().len()),
                Event::Empty(e) => (true, e.name().as_ref().len()),
                Event::End(_) => {
                    stack.pop();
                    if stack.is_empty() {
                        root_done = true;
                    }
                    continue;
                }
                Event::Text(_) => {
                    if let Some(&(open, _)) = stack.last() {
                        if let Some(node) = doc.nodes.get_mut(open as usize) {
                            if node.text_end == node.text_start {
                                node.text_start = before as u32;
                            }
                            node.text_end = after as u32;
                        }
                    }
                    continue;
                }
                Event::Eof => break,
                _ => continue,
            };
            if root_done {
                return fail(doc, &stack, before, "a second root element".into());
            }
            if doc.nodes.len() >= MAX_ELEMENTS {
                return fail(doc, &stack, before, format!("more than {MAX_ELEMENTS} elements: far beyond a real export"));
            }
            if !empty && stack.len() >= MAX_NESTING {
                return fail(doc, &stack, before, format!("elements nested more than {MAX_NESTING} deep: far beyond a real export"));
            }
            let id = doc.nodes.len() as u32;
            let name_end = (before + 1 + name_len) as u32;
            let attrs_end = after.saturating_sub(if empty { 2 } else { 1 }).max(name_end as usize);
            let parent = stack.last().map_or(NONE, |&(p, _)| p);
            doc.nodes.push(Node {
                start: before as u32,
                name_end,
                attrs_end: attrs_end as u32,
                text_start: 0,
                text_end: 0,
                parent,
                first_child: NONE,
                next_sibling: NONE,
            });
            if let Some((p, last)) = stack.last_mut() {
                if *last == NONE {
                    if let Some(pn) = doc.nodes.get_mut(*p as usize) {
                        pn.first_child = id;
                    }
                } else if let Some(ln) = doc.nodes.get_mut(*last as usize) {
                    ln.next_sibling = id;
                }
                *last = id;
            }
            if empty {
                if stack.is_empty() {
                    root_done = true;
                }
            } else {
                stack.push((id, NONE));
            }
        }
        if !stack.is_empty() {
            let len = bytes.len();
            let name = stack.last().map(|&(n, _)| String::from_utf8_lossy(doc.name(n)).into_owned()).unwrap_or_default();
            return fail(doc, &stack, len, format!("unexpected end of file: <{name}> is not closed (truncated file?)"));
        }
        if doc.nodes.is_empty() {
            return fail(doc, &stack, bytes.len(), "no root element".into());
        }
        Ok(doc)
    }

    /// The root element.
    pub fn root(&self) -> NodeId {
        0
    }

    fn node(&self, id: NodeId) -> Option<&Node> {
        self.nodes.get(id as usize)
    }

    /// The element's name (empty for an invalid id).
    pub fn name(&self, id: NodeId) -> &'a [u8] {
        self.node(id).and_then(|n| self.bytes.get(n.start as usize + 1..n.name_end as usize)).unwrap_or_default()
    }

    /// Raw text directly inside the element (entities not decoded, not trimmed).
    pub fn text(&self, id: NodeId) -> &'a [u8] {
        self.node(id).and_then(|n| self.bytes.get(n.text_start as usize..n.text_end as usize)).unwrap_or_default()
    }

    /// Byte offset of the element's start tag.
    pub fn offset(&self, id: NodeId) -> usize {
        self.node(id).map_or(0, |n| n.start as usize)
    }

    pub fn parent(&self, id: NodeId) -> Option<NodeId> {
        self.node(id).map(|n| n.parent).filter(|&p| p != NONE)
    }

    /// Child elements in document order.
    pub fn children(&self, id: NodeId) -> Children<'_, 'a> {
        Children { doc: self, next: self.node(id).map_or(NONE, |n| n.first_child) }
    }

    /// The first child element called `name`.
    pub fn child(&self, id: NodeId, name: &[u8]) -> Option<NodeId> {
        self.children(id).find(|&c| self.name(c) == name)
    }

    /// Follows a path of child names, taking the first match at every step.
    pub fn descend(&self, id: NodeId, path: &[&[u8]]) -> Option<NodeId> {
        path.iter().try_fold(id, |at, name| self.child(at, name))
    }

    /// The raw (not unescaped) value of attribute `key`; `Err` with a message when the start
    /// tag's attributes are malformed.
    pub fn attr(&self, id: NodeId, key: &[u8]) -> Result<Option<&'a [u8]>, String> {
        let Some(n) = self.node(id) else {
            return Ok(None);
        };
        if n.attrs_end <= n.name_end {
            return Ok(None);
        }
        let tag = self.bytes.get(n.start as usize + 1..n.attrs_end as usize).unwrap_or_default();
        let tag = std::str::from_utf8(tag).map_err(|_| "attribute is not valid UTF-8".to_owned())?;
        let name_len = (n.name_end - n.start - 1) as usize;
        for attr in Attributes::new(tag, name_len) {
            let attr = attr.map_err(|e| e.to_string())?;
            if attr.key.as_ref() == key {
                // Attributes of a borrowed `&str` are borrowed from it, hence from `bytes`.
                return Ok(Some(match attr.value {
                    std::borrow::Cow::Borrowed(v) => v,
                    std::borrow::Cow::Owned(_) => return Err("unexpected attribute form".into()),
                }));
            }
        }
        Ok(None)
    }
}

/// Iterator over an element's children.
pub(crate) struct Children<'d, 'a> {
    doc: &'d Doc<'a>,
    next: u32,
}

impl Iterator for Children<'_, '_> {
    type Item = NodeId;
    fn next(&mut self) -> Option<NodeId> {
        let id = self.next;
        let node = self.doc.node(id)?;
        self.next = node.next_sibling;
        Some(id)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tree_names_text_attrs() {
        let xml = br#"<?xml version="1.0"?>
<!-- c --><r a="1"><x>"hi"</x><y ref="7"/><z>
  <w>1,2</w> </z><x>two</x></r>"#;
        let doc = Doc::build(xml).map_err(|e| e.message).expect("builds");
        let r = doc.root();
        assert_eq!(doc.name(r), b"r");
        assert_eq!(doc.attr(r, b"a"), Ok(Some(&b"1"[..])));
        let kids: Vec<_> = doc.children(r).map(|c| doc.name(c)).collect();
        assert_eq!(kids, vec![&b"x"[..], b"y", b"z", b"x"]);
        let x = doc.child(r, b"x").expect("x");
        assert_eq!(doc.text(x), b"\"hi\"");
        let y = doc.child(r, b"y").expect("y");
        assert_eq!(doc.attr(y, b"ref"), Ok(Some(&b"7"[..])));
        assert_eq!(doc.attr(y, b"nope"), Ok(None));
        let w = doc.descend(r, &[b"z", b"w"]).expect("w");
        assert_eq!(doc.text(w), b"1,2");
        assert_eq!(doc.parent(w), doc.child(r, b"z"));
        assert_eq!(&xml[doc.offset(w)..doc.offset(w) + 3], b"<w>");
    }

    #[test]
    fn truncated_is_an_error() {
        let err = Doc::build(b"<r><x>1</x><y>").err().expect("error");
        assert!(err.message.contains("not closed"), "{}", err.message);
        let err = Doc::build(b"<r><x>1</x><y").err().expect("error");
        assert!(!err.message.is_empty());
        assert!(Doc::build(b"<r></q>").is_err());
        assert!(Doc::build(b"").is_err());
    }
}

#[cfg(test)]
mod limit_tests {
    use super::*;

    fn build_error(text: &str) -> String {
        match Doc::build(text.as_bytes()) {
            Ok(_) => "built".to_string(),
            Err(e) => e.message,
        }
    }

    #[test]
    fn nesting_is_bounded() {
        let ok = format!("<r>{}{}</r>", "<a>".repeat(MAX_NESTING - 2), "</a>".repeat(MAX_NESTING - 2));
        assert_eq!(build_error(&ok), "built");
        // An unclosed file a million elements deep is refused at the limit, not read to the end.
        let deep = format!("<r>{}", "<a>".repeat(1_000_000));
        assert!(build_error(&deep).contains(&format!("nested more than {MAX_NESTING} deep")));
    }

    #[test]
    fn element_count_is_bounded() {
        let many = format!("<r>{}</r>", "<a/>".repeat(MAX_ELEMENTS));
        assert!(build_error(&many).contains(&format!("more than {MAX_ELEMENTS} elements")));
        let fewer = format!("<r>{}</r>", "<a/>".repeat(MAX_ELEMENTS - 1));
        assert_eq!(build_error(&fewer), "built");
    }
}
