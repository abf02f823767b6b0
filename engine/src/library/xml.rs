//! The library's XML exchange format (documented in `docs/library-xml.md`), read and written
//! with quick-xml.
//!
//! ```xml
//! <motorLibrary version="1">
//!   <class id="…" name="…" domain="motor" modelicaClass="cad2mo.Drives.Motors.DCPermanentMagnet">
//!     <description>…</description>
//!     <parameter name="L" type="Real" unit="H" min="0" editable="false" default="8.2e-5">Armature inductance</parameter>
//!     <parameter name="T_nom" type="Real" unit="N.m" min="0" editable="false" datasheet="true">Nominal torque</parameter>
//!   </class>
//!   <instance id="…" class="…" name="…" source="…">
//!     <value param="L">8.23e-5</value>
//!   </instance>
//! </motorLibrary>
//! ```
//!
//! [`read`] only parses (syntax, elements, attributes, numbers): the library rules are applied by
//! [`super::plan_import`], which also knows the classes already in the library. Problems name the
//! line and the element.

use std::borrow::Cow;

use quick_xml::events::attributes::Attribute;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};
use quick_xml::name::QName;
use quick_xml::{Reader, Writer};
use serde_json::{Map, Value as Json};

use super::{Class, Issue, Library, ParamType, Parameter, Value};
use super::{ClassDraft, ParameterDraft};

/// The format version written and accepted.
pub const VERSION: &str = "1";

/// A class as read from the file.
#[derive(Clone, Debug, PartialEq)]
pub struct XmlClass {
    pub line: usize,
    pub id: String,
    pub draft: ClassDraft,
    /// The line of each `<parameter>`, in order.
    pub param_lines: Vec<usize>,
}

/// One `<value>`.
#[derive(Clone, Debug, PartialEq)]
pub struct XmlValue {
    pub line: usize,
    pub param: String,
    /// The optional `unit` attribute.
    pub unit: Option<String>,
    pub text: String,
}

/// An instance as read from the file; values stay text until the class is known.
#[derive(Clone, Debug, PartialEq)]
pub struct XmlInstance {
    pub line: usize,
    pub id: String,
    pub class_id: String,
    pub name: String,
    pub source: String,
    pub values: Vec<XmlValue>,
}

/// A parsed file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    pub classes: Vec<XmlClass>,
    pub instances: Vec<XmlInstance>,
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Escapes an attribute value; line breaks and tabs become character references so that they
/// survive attribute-value normalisation by any XML reader.
fn attr_escape(s: &str) -> String {
    quick_xml::escape::partial_escape(s).replace('"', "&quot;").replace('\n', "&#10;").replace('\r', "&#13;").replace('\t', "&#9;")
}

/// A text node; carriage returns become references too (XML readers turn a raw CR LF into LF).
fn text_event(s: &str) -> BytesText<'static> {
    BytesText::from_escaped(quick_xml::escape::partial_escape(s).replace('\r', "&#13;"))
}

fn start<'a>(name: &'a str, attrs: &[(&'a str, String)]) -> BytesStart<'a> {
    let mut e = BytesStart::new(name);
    for (k, v) in attrs {
        e.push_attribute(Attribute { key: QName(k.as_bytes()), value: Cow::Owned(attr_escape(v).into_bytes()) });
    }
    e
}

/// Writes `<name attrs>text</name>`, or `<name attrs/>` when `text` is empty.
fn element<W: std::io::Write>(w: &mut Writer<W>, name: &str, attrs: &[(&str, String)], text: &str) -> std::io::Result<()> {
    if text.is_empty() {
        w.write_event(Event::Empty(start(name, attrs)))
    } else {
        w.write_event(Event::Start(start(name, attrs)))?;
        w.write_event(Event::Text(text_event(text)))?;
        w.write_event(Event::End(BytesEnd::new(name)))
    }
}

fn parameter_attrs(p: &Parameter) -> Vec<(&'static str, String)> {
    let mut a = vec![("name", p.name.clone()), ("type", p.ty.as_str().to_string())];
    if !p.unit.is_empty() {
        a.push(("unit", p.unit.clone()));
    }
    if let Some(x) = p.min {
        a.push(("min", Value::Real(x).to_text()));
    }
    if let Some(x) = p.max {
        a.push(("max", Value::Real(x).to_text()));
    }
    a.push(("editable", p.editable.to_string()));
    if p.datasheet {
        a.push(("datasheet", "true".to_string()));
    }
    if let Some(d) = &p.default {
        a.push(("default", d.to_text()));
    }
    a
}

fn write_class<W: std::io::Write>(w: &mut Writer<W>, c: &Class) -> std::io::Result<()> {
    let attrs = [("id", c.id.clone()), ("name", c.name.clone()), ("domain", c.domain.clone()), ("modelicaClass", c.modelica_class.clone())];
    w.write_event(Event::Start(start("class", &attrs)))?;
    element(w, "description", &[], &c.description)?;
    for p in &c.parameters {
        element(w, "parameter", &parameter_attrs(p), &p.comment)?;
    }
    w.write_event(Event::End(BytesEnd::new("class")))
}

/// Writes the library (in the order given; see [`Library::sort`]) as an XML document.
pub fn write(lib: &Library) -> String {
    let mut w = Writer::new_with_indent(Vec::new(), b' ', 2);
    let result: std::io::Result<()> = (|| {
        w.write_event(Event::Decl(BytesDecl::new("1.0", Some("UTF-8"), None)))?;
        w.write_event(Event::Start(start("motorLibrary", &[("version", VERSION.to_string())])))?;
        for c in &lib.classes {
            write_class(&mut w, c)?;
        }
        for i in &lib.instances {
            let attrs = [("id", i.id.clone()), ("class", i.class_id.clone()), ("name", i.name.clone()), ("source", i.source.clone())];
            if i.values.is_empty() {
                w.write_event(Event::Empty(start("instance", &attrs)))?;
                continue;
            }
            w.write_event(Event::Start(start("instance", &attrs)))?;
            for (param, v) in &i.values {
                // An empty string value is written as <value param="x"></value> (not <value/>,
                // which reads the same, but this is clearer).
                w.write_event(Event::Start(start("value", &[("param", param.clone())])))?;
                w.write_event(Event::Text(text_event(&v.to_text())))?;
                w.write_event(Event::End(BytesEnd::new("value")))?;
            }
            w.write_event(Event::End(BytesEnd::new("instance")))?;
        }
        w.write_event(Event::End(BytesEnd::new("motorLibrary")))
    })();
    // Writing into a Vec cannot fail; the text is UTF-8 because every piece is.
    debug_assert!(result.is_ok());
    let mut text = String::from_utf8(w.into_inner()).unwrap_or_default();
    text.push('\n');
    text
}

// ---------------------------------------------------------------------------------------------
// Reading

/// Where an element starts, for messages.
#[derive(Clone, Debug)]
struct At {
    line: usize,
    tag: String,
}

impl At {
    fn field(&self) -> String {
        format!("line {} <{}>", self.line, self.tag)
    }
}

/// Line (1-based) of a byte offset.
fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end].iter().filter(|b| **b == b'\n').count() + 1
}

/// The attributes of an element, unescaped, with unknown or repeated ones reported.
fn attributes(e: &BytesStart<'_>, at: &At, allowed: &[&str], issues: &mut Vec<Issue>) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for a in e.attributes() {
        let a = match a {
            Ok(a) => a,
            Err(err) => {
                issues.push(Issue::new(at.field(), format!("bad attribute: {err}")));
                continue;
            }
        };
        let key = String::from_utf8_lossy(a.key.as_ref()).into_owned();
        let value = match a.unescape_value() {
            Ok(v) => v.into_owned(),
            Err(err) => {
                issues.push(Issue::new(at.field(), format!("attribute {key}: {err}")));
                continue;
            }
        };
        if !allowed.contains(&key.as_str()) {
            issues.push(Issue::new(at.field(), format!("unknown attribute \"{key}\" (allowed: {})", allowed.join(", "))));
        } else if out.iter().any(|(k, _)| *k == key) {
            issues.push(Issue::new(at.field(), format!("attribute \"{key}\" appears twice")));
        } else {
            out.push((key, value));
        }
    }
    out
}

fn take(attrs: &mut Vec<(String, String)>, key: &str) -> Option<String> {
    let i = attrs.iter().position(|(k, _)| k == key)?;
    Some(attrs.remove(i).1)
}

fn required(attrs: &mut Vec<(String, String)>, key: &str, at: &At, issues: &mut Vec<Issue>) -> String {
    take(attrs, key).unwrap_or_else(|| {
        issues.push(Issue::new(at.field(), format!("the attribute \"{key}\" is missing")));
        String::new()
    })
}

fn parse_real(text: &str) -> Option<f64> {
    let t = text.trim();
    // Rust also accepts "inf", "NaN", "+1"...; only finite decimal numbers are values here.
    let ok = !t.is_empty()
        && t.chars().all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+'))
        && t.chars().any(|c| c.is_ascii_digit());
    t.parse::<f64>().ok().filter(|x| ok && x.is_finite())
}

fn parse_bool(text: &str) -> Option<bool> {
    match text.trim() {
        "true" | "1" => Some(true),
        "false" | "0" => Some(false),
        _ => None,
    }
}

/// Text of a value of type `ty` as the JSON [`super::check_value`] takes; `None` if the text is
/// not of that type.
fn text_to_json(ty: ParamType, text: &str) -> Option<Json> {
    match ty {
        ParamType::Real => parse_real(text).and_then(serde_json::Number::from_f64).map(Json::Number),
        ParamType::Integer => text.trim().parse::<i64>().ok().map(Json::from),
        ParamType::Boolean => parse_bool(text).map(Json::Bool),
        ParamType::String => Some(Json::String(text.to_string())),
    }
}

fn type_words(ty: ParamType) -> &'static str {
    match ty {
        ParamType::Real => "a decimal number such as 0.317 or 8.2e-5",
        ParamType::Integer => "a whole number",
        ParamType::Boolean => "true or false",
        ParamType::String => "text",
    }
}

impl XmlInstance {
    /// The values as JSON for `class` (typed by its parameters; a `unit` attribute becomes
    /// `{"value": x, "unit": u}`). Values of unknown parameters are passed on as strings, for
    /// the instance check to report.
    pub fn values_json(&self, class: &Class) -> Result<Map<String, Json>, Vec<Issue>> {
        let mut map = Map::new();
        let mut issues = Vec::new();
        for v in &self.values {
            let at = format!("line {} <value param={:?}>", v.line, v.param);
            if map.contains_key(&v.param) {
                issues.push(Issue::new(at, format!("{} is given twice", v.param)));
                continue;
            }
            let json = match class.parameter(&v.param) {
                None => Json::String(v.text.clone()),
                Some(p) => match text_to_json(p.ty, &v.text) {
                    Some(x) => match &v.unit {
                        Some(u) => serde_json::json!({"value": x, "unit": u}),
                        None => x,
                    },
                    None => {
                        issues.push(Issue::new(at, format!("{}: \"{}\" is not {} ({})", p.name, v.text, type_words(p.ty), p.ty.as_str())));
                        continue;
                    }
                },
            };
            map.insert(v.param.clone(), json);
        }
        if issues.is_empty() {
            Ok(map)
        } else {
            Err(issues)
        }
    }
}

/// What is open while reading.
enum Open {
    Root,
    Class(XmlClass),
    Description { text: String },
    Parameter { text: String, at: At, draft: ParameterDraft, default: Option<String>, ok: bool },
    Instance(XmlInstance),
    Value { text: String, value: XmlValue },
}

impl Open {
    fn text_mut(&mut self) -> Option<&mut String> {
        match self {
            Open::Description { text } | Open::Parameter { text, .. } | Open::Value { text, .. } => Some(text),
            _ => None,
        }
    }
}

fn parse_parameter(e: &BytesStart<'_>, at: At, issues: &mut Vec<Issue>) -> Open {
    let before = issues.len();
    let mut a = attributes(e, &at, &["name", "type", "unit", "min", "max", "editable", "datasheet", "default"], issues);
    let name = required(&mut a, "name", &at, issues);
    let ty = required(&mut a, "type", &at, issues);
    let unit = take(&mut a, "unit").unwrap_or_default();
    let mut limit = |key: &str| {
        take(&mut a, key).and_then(|t| {
            let x = parse_real(&t);
            if x.is_none() {
                issues.push(Issue::new(at.field(), format!("{key} \"{t}\" is not a finite decimal number")));
            }
            x
        })
    };
    let min = limit("min");
    let max = limit("max");
    let editable = match take(&mut a, "editable") {
        None => false,
        Some(t) => parse_bool(&t).unwrap_or_else(|| {
            issues.push(Issue::new(at.field(), format!("editable \"{t}\" must be true or false")));
            false
        }),
    };
    let datasheet = match take(&mut a, "datasheet") {
        None => false,
        Some(t) => parse_bool(&t).unwrap_or_else(|| {
            issues.push(Issue::new(at.field(), format!("datasheet \"{t}\" must be true or false")));
            false
        }),
    };
    let default = take(&mut a, "default");
    let ok = issues.len() == before;
    let draft = ParameterDraft { name, ty, unit, min, max, editable, datasheet, default: None, comment: String::new() };
    Open::Parameter { text: String::new(), at, draft, default, ok }
}

/// Parses a library file. Syntax errors stop the reading; other problems are collected.
pub fn read(text: &str) -> Result<Document, Vec<Issue>> {
    let mut reader = Reader::from_str(text);
    reader.config_mut().expand_empty_elements = true;
    reader.config_mut().trim_text(false);
    let mut doc = Document::default();
    let mut issues = Vec::new();
    let mut stack: Vec<Open> = Vec::new();
    let mut seen_root = false;
    loop {
        let offset = reader.buffer_position() as usize;
        let event = match reader.read_event() {
            Ok(e) => e,
            Err(err) => {
                let line = line_of(text, reader.error_position() as usize);
                // The syntax error first: it is why reading stopped.
                issues.insert(0, Issue::new(format!("line {line}"), format!("malformed XML: {err}")));
                return Err(issues);
            }
        };
        match event {
            Event::Start(e) => {
                let tag = String::from_utf8_lossy(e.name().as_ref()).into_owned();
                let at = At { line: line_of(text, offset), tag: tag.clone() };
                let parent = stack.last().map(|o| match o {
                    Open::Root => "motorLibrary",
                    Open::Class(_) => "class",
                    Open::Description { .. } => "description",
                    Open::Parameter { .. } => "parameter",
                    Open::Instance(_) => "instance",
                    Open::Value { .. } => "value",
                });
                let open = match (parent, tag.as_str()) {
                    (None, "motorLibrary") if !seen_root => {
                        seen_root = true;
                        let mut a = attributes(&e, &at, &["version"], &mut issues);
                        match take(&mut a, "version") {
                            Some(v) if v == VERSION => {}
                            Some(v) => issues.push(Issue::new(
                                at.field(),
                                format!("version \"{v}\" is not supported (this service reads version {VERSION})"),
                            )),
                            None => issues.push(Issue::new(at.field(), "the attribute \"version\" is missing")),
                        }
                        Open::Root
                    }
                    (None, _) => {
                        issues.push(Issue::new(at.field(), "the root element must be <motorLibrary version=\"1\">"));
                        return Err(issues);
                    }
                    (Some("motorLibrary"), "class") => {
                        let mut a = attributes(&e, &at, &["id", "name", "domain", "modelicaClass"], &mut issues);
                        let id = required(&mut a, "id", &at, &mut issues);
                        let name = required(&mut a, "name", &at, &mut issues);
                        let domain = required(&mut a, "domain", &at, &mut issues);
                        let modelica_class = required(&mut a, "modelicaClass", &at, &mut issues);
                        Open::Class(XmlClass {
                            line: at.line,
                            id,
                            draft: ClassDraft { name, domain, modelica_class, ..ClassDraft::default() },
                            param_lines: Vec::new(),
                        })
                    }
                    (Some("motorLibrary"), "instance") => {
                        let mut a = attributes(&e, &at, &["id", "class", "name", "source"], &mut issues);
                        let id = required(&mut a, "id", &at, &mut issues);
                        let class_id = required(&mut a, "class", &at, &mut issues);
                        let name = required(&mut a, "name", &at, &mut issues);
                        let source = take(&mut a, "source").unwrap_or_default();
                        Open::Instance(XmlInstance { line: at.line, id, class_id, name, source, values: Vec::new() })
                    }
                    (Some("class"), "description") => {
                        attributes(&e, &at, &[], &mut issues);
                        Open::Description { text: String::new() }
                    }
                    (Some("class"), "parameter") => parse_parameter(&e, at, &mut issues),
                    (Some("instance"), "value") => {
                        let mut a = attributes(&e, &at, &["param", "unit"], &mut issues);
                        let param = required(&mut a, "param", &at, &mut issues);
                        let unit = take(&mut a, "unit");
                        Open::Value { text: String::new(), value: XmlValue { line: at.line, param, unit, text: String::new() } }
                    }
                    (Some(p), _) => {
                        let expected = match p {
                            "motorLibrary" => "<class> or <instance>",
                            "class" => "<description> or <parameter>",
                            "instance" => "<value>",
                            _ => "text only",
                        };
                        issues.push(Issue::new(at.field(), format!("unexpected element <{tag}> in <{p}> (expected {expected})")));
                        return Err(issues);
                    }
                };
                stack.push(open);
            }
            Event::End(_) => {
                let Some(done) = stack.pop() else { continue };
                match (done, stack.last_mut()) {
                    (Open::Class(c), _) => doc.classes.push(c),
                    (Open::Instance(i), _) => doc.instances.push(i),
                    (Open::Description { text }, Some(Open::Class(c))) => c.draft.description = text,
                    (Open::Parameter { text, at, mut draft, default, ok }, Some(Open::Class(c))) => {
                        draft.comment = text;
                        if let Some(d) = default {
                            match ParamType::parse(&draft.ty) {
                                Some(ty) => match text_to_json(ty, &d) {
                                    Some(j) => draft.default = Some(j),
                                    None => issues.push(Issue::new(
                                        at.field(),
                                        format!("default \"{d}\" of {} is not {}", draft.name, type_words(ty)),
                                    )),
                                },
                                // The unknown type is reported by the class check.
                                None => draft.default = Some(Json::String(d)),
                            }
                        }
                        if ok {
                            c.param_lines.push(at.line);
                            c.draft.parameters.push(draft);
                        }
                    }
                    (Open::Value { text, mut value }, Some(Open::Instance(i))) => {
                        value.text = text;
                        i.values.push(value);
                    }
                    _ => {}
                }
            }
            Event::Text(t) => {
                let s = match t.unescape() {
                    Ok(s) => s,
                    Err(err) => {
                        let line = line_of(text, offset);
                        issues.push(Issue::new(format!("line {line}"), format!("malformed text: {err}")));
                        return Err(issues);
                    }
                };
                match stack.last_mut().and_then(Open::text_mut) {
                    Some(buf) => buf.push_str(&s),
                    None if s.trim().is_empty() => {}
                    None => {
                        let line = line_of(text, offset);
                        issues.push(Issue::new(format!("line {line}"), format!("unexpected text \"{}\"", s.trim())));
                    }
                }
            }
            Event::CData(t) => {
                let s = String::from_utf8_lossy(&t).into_owned();
                match stack.last_mut().and_then(Open::text_mut) {
                    Some(buf) => buf.push_str(&s),
                    None => {
                        let line = line_of(text, offset);
                        issues.push(Issue::new(format!("line {line}"), "unexpected CDATA section"));
                    }
                }
            }
            Event::Eof => break,
            // Declaration, comments, processing instructions, doctype.
            _ => {}
        }
    }
    if !seen_root {
        issues.push(Issue::new("line 1", "no <motorLibrary> element: this is not a motor library file"));
    } else if !stack.is_empty() {
        issues.push(Issue::new(format!("line {}", line_of(text, text.len())), "the file ends inside an element"));
    }
    if issues.is_empty() {
        Ok(doc)
    } else {
        Err(issues)
    }
}
