//! A small, independent reader of the Modelica subset that `Mechanics.mo` is written in.
//!
//! It knows nothing of the converter: it tokenizes the text (identifiers, numbers, strings with
//! escapes, `//` and `/* */` comments) and parses one model made of component declarations
//! (`[prefixes] Type name[(modifiers)] ["description"] [annotation(...)];`) and an equation
//! section of `connect(a.b, c.d);`. Annotations are skipped; modifiers are kept as [`Value`]s
//! keyed by their path (`r`, `n_x`, `phi.start`, `phi.fixed`, ...). Errors name the line and
//! what was unexpected.

use std::collections::BTreeMap;
use std::fmt;

/// A modifier value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Num(f64),
    Vec(Vec<f64>),
    Str(String),
    Bool(bool),
    /// A (possibly dotted) name, e.g. an enumeration literal.
    Ident(String),
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Num(x) => write!(f, "{x:?}"),
            Value::Vec(v) => {
                let parts: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
                write!(f, "{{{}}}", parts.join(", "))
            }
            Value::Str(s) => write!(f, "{s:?}"),
            Value::Bool(b) => write!(f, "{b}"),
            Value::Ident(s) => f.write_str(s),
        }
    }
}

/// One component declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct Component {
    /// The type as written, e.g. `Modelica.Mechanics.MultiBody.Parts.Body`.
    pub class: String,
    pub name: String,
    /// Modifiers by path: `r`, `n`, `m`, `I_11`, `phi.start`, `phi.fixed`, `s.start`, ...
    pub params: BTreeMap<String, Value>,
}

impl Component {
    /// A numeric modifier.
    pub fn num(&self, key: &str) -> Option<f64> {
        match self.params.get(key)? {
            Value::Num(x) => Some(*x),
            _ => None,
        }
    }

    /// A vector modifier.
    pub fn vector(&self, key: &str) -> Option<&[f64]> {
        match self.params.get(key)? {
            Value::Vec(v) => Some(v),
            _ => None,
        }
    }

    /// A string modifier.
    pub fn string(&self, key: &str) -> Option<&str> {
        match self.params.get(key)? {
            Value::Str(s) => Some(s),
            _ => None,
        }
    }
}

/// The parsed `Mechanics.mo`.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    /// The package of `within PKG;` (empty for `within ;` or no `within`).
    pub package: String,
    pub components: Vec<Component>,
    /// `connect(a, b)` pairs, in file order, as written (`LINK.frame_a`).
    pub connects: Vec<(String, String)>,
}

impl Model {
    /// The component called `name`.
    pub fn component(&self, name: &str) -> Option<&Component> {
        self.components.iter().find(|c| c.name == name)
    }

    /// The components whose class is `class`.
    pub fn of_class<'a>(&'a self, class: &'a str) -> impl Iterator<Item = &'a Component> + 'a {
        self.components.iter().filter(move |c| c.class == class)
    }
}

// ---------------------------------------------------------------------------------------------
// Tokenizer

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Num(f64),
    Str(String),
    Sym(char),
}

impl fmt::Display for Tok {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tok::Ident(s) => write!(f, "`{s}`"),
            Tok::Num(x) => write!(f, "number {x:?}"),
            Tok::Str(s) => {
                let short: String = s.chars().take(40).collect();
                let more = if s.chars().count() > 40 { "..." } else { "" };
                write!(f, "string {short:?}{more}")
            }
            Tok::Sym(c) => write!(f, "`{c}`"),
        }
    }
}

#[derive(Clone, Debug)]
struct Token {
    tok: Tok,
    line: usize,
}

const SYMBOLS: &str = "(){}[],;=.+-*/:<>^";

fn tokenize(text: &str) -> Result<Vec<Token>, String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut line = 1;
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let start = line;
            i += 2;
            loop {
                match chars.get(i) {
                    None => return Err(format!("line {start}: unterminated /* comment")),
                    Some('*') if chars.get(i + 1) == Some(&'/') => {
                        i += 2;
                        break;
                    }
                    Some(ch) => {
                        if *ch == '\n' {
                            line += 1;
                        }
                        i += 1;
                    }
                }
            }
        } else if c == '"' {
            let start = line;
            let mut s = String::new();
            i += 1;
            loop {
                match chars.get(i) {
                    None => return Err(format!("line {start}: unterminated string")),
                    Some('"') => {
                        i += 1;
                        break;
                    }
                    Some('\\') => {
                        let e = chars.get(i + 1).copied();
                        let decoded = match e {
                            Some('"') => '"',
                            Some('\'') => '\'',
                            Some('\\') => '\\',
                            Some('?') => '?',
                            Some('a') => '\u{7}',
                            Some('b') => '\u{8}',
                            Some('f') => '\u{c}',
                            Some('n') => '\n',
                            Some('r') => '\r',
                            Some('t') => '\t',
                            Some('v') => '\u{b}',
                            Some(other) => {
                                return Err(format!("line {line}: unknown escape `\\{other}` in a string"));
                            }
                            None => return Err(format!("line {start}: unterminated string")),
                        };
                        s.push(decoded);
                        i += 2;
                    }
                    Some(ch) => {
                        if *ch == '\n' {
                            line += 1;
                        }
                        s.push(*ch);
                        i += 1;
                    }
                }
            }
            out.push(Token { tok: Tok::Str(s), line: start });
        } else if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push(Token { tok: Tok::Ident(chars[start..i].iter().collect()), line });
        } else if c.is_ascii_digit() {
            // UNSIGNED_NUMBER = digits [ "." [ digits ] ] [ ("e" | "E") [ "+" | "-" ] digits ]
            let start = i;
            let digits = |i: &mut usize| {
                while *i < chars.len() && chars[*i].is_ascii_digit() {
                    *i += 1;
                }
            };
            digits(&mut i);
            if chars.get(i) == Some(&'.') {
                i += 1;
                digits(&mut i);
            }
            if matches!(chars.get(i), Some('e' | 'E')) {
                i += 1;
                if matches!(chars.get(i), Some('+' | '-')) {
                    i += 1;
                }
                let exp_start = i;
                digits(&mut i);
                if i == exp_start {
                    return Err(format!("line {line}: malformed number exponent"));
                }
            }
            if chars.get(i).is_some_and(|ch| ch.is_ascii_alphabetic() || *ch == '_') {
                return Err(format!("line {line}: malformed number (a letter follows it)"));
            }
            let text: String = chars[start..i].iter().collect();
            let x: f64 = text.parse().map_err(|e| format!("line {line}: malformed number `{text}`: {e}"))?;
            out.push(Token { tok: Tok::Num(x), line });
        } else if SYMBOLS.contains(c) {
            out.push(Token { tok: Tok::Sym(c), line });
            i += 1;
        } else {
            return Err(format!("line {line}: unexpected character {c:?}"));
        }
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------------------
// Parser

/// Prefixes a declaration may carry; they do not change what we read.
const PREFIXES: &[&str] =
    &["inner", "outer", "parameter", "constant", "final", "discrete", "input", "output", "flow", "stream", "replaceable"];

struct Parser {
    toks: Vec<Token>,
    pos: usize,
    last_line: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|t| &t.tok)
    }

    fn line(&self) -> usize {
        self.toks.get(self.pos).map_or(self.last_line, |t| t.line)
    }

    fn describe_next(&self) -> String {
        self.peek().map_or_else(|| "end of file".to_string(), |t| t.to_string())
    }

    fn err(&self, expected: &str) -> String {
        format!("line {}: expected {expected}, found {}", self.line(), self.describe_next())
    }

    fn bump(&mut self) -> Option<Tok> {
        let t = self.toks.get(self.pos)?.tok.clone();
        self.pos += 1;
        Some(t)
    }

    fn is_sym(&self, c: char) -> bool {
        self.peek() == Some(&Tok::Sym(c))
    }

    fn is_kw(&self, kw: &str) -> bool {
        matches!(self.peek(), Some(Tok::Ident(s)) if s == kw)
    }

    fn eat_sym(&mut self, c: char) -> bool {
        let yes = self.is_sym(c);
        if yes {
            self.pos += 1;
        }
        yes
    }

    fn eat_kw(&mut self, kw: &str) -> bool {
        let yes = self.is_kw(kw);
        if yes {
            self.pos += 1;
        }
        yes
    }

    fn expect_sym(&mut self, c: char) -> Result<(), String> {
        if self.eat_sym(c) {
            Ok(())
        } else {
            Err(self.err(&format!("`{c}`")))
        }
    }

    fn ident(&mut self, what: &str) -> Result<String, String> {
        match self.peek() {
            Some(Tok::Ident(s)) => {
                let s = s.clone();
                self.pos += 1;
                Ok(s)
            }
            _ => Err(self.err(what)),
        }
    }

    /// `a.b.c`
    fn dotted(&mut self, what: &str) -> Result<String, String> {
        let mut s = self.ident(what)?;
        while self.is_sym('.') {
            self.pos += 1;
            s.push('.');
            s.push_str(&self.ident(what)?);
        }
        Ok(s)
    }

    /// Skips a balanced `( ... )`, the opening parenthesis being next.
    fn skip_parens(&mut self) -> Result<(), String> {
        let start = self.line();
        self.expect_sym('(')?;
        let mut depth = 1usize;
        while depth > 0 {
            match self.bump() {
                None => return Err(format!("line {start}: unbalanced parentheses (end of file inside)")),
                Some(Tok::Sym('(')) => depth += 1,
                Some(Tok::Sym(')')) => depth -= 1,
                Some(_) => {}
            }
        }
        Ok(())
    }

    /// `"a" [+ "b" ...]`, if present.
    fn description(&mut self) -> Result<Option<String>, String> {
        let Some(Tok::Str(first)) = self.peek() else { return Ok(None) };
        let mut s = first.clone();
        self.pos += 1;
        while self.is_sym('+') {
            self.pos += 1;
            match self.bump() {
                Some(Tok::Str(more)) => s.push_str(&more),
                _ => {
                    self.pos -= 1;
                    return Err(self.err("a string after `+` in a description"));
                }
            }
        }
        Ok(Some(s))
    }

    /// `annotation (...)`, if present.
    fn annotation(&mut self) -> Result<bool, String> {
        if self.eat_kw("annotation") {
            self.skip_parens()?;
            Ok(true)
        } else {
            Ok(false)
        }
    }

    /// The arguments of a modification, after its `(`, up to and including its `)`.
    fn modification(&mut self, prefix: &str, out: &mut BTreeMap<String, Value>) -> Result<(), String> {
        if self.eat_sym(')') {
            return Ok(());
        }
        loop {
            while self.eat_kw("each") || self.eat_kw("final") {}
            if self.is_kw("redeclare") || self.is_kw("replaceable") {
                return Err(format!("line {}: `redeclare`/`replaceable` modifiers are not supported", self.line()));
            }
            let line = self.line();
            let name = self.dotted("a modifier name")?;
            let key = format!("{prefix}{name}");
            let mut any = false;
            if self.eat_sym('(') {
                self.modification(&format!("{key}."), out)?;
                any = true;
            }
            if self.eat_sym('=') {
                let v = self.expr()?;
                if out.insert(key.clone(), v).is_some() {
                    return Err(format!("line {line}: modifier `{key}` given twice"));
                }
                any = true;
            }
            if !any {
                return Err(self.err(&format!("`=` or `(` after modifier `{key}`")));
            }
            self.description()?;
            if self.eat_sym(')') {
                return Ok(());
            }
            if !self.eat_sym(',') {
                return Err(self.err("`,` or `)` in a modifier list"));
            }
        }
    }

    fn expr(&mut self) -> Result<Value, String> {
        let mut v = self.term()?;
        loop {
            let line = self.line();
            let op = if self.eat_sym('+') {
                '+'
            } else if self.eat_sym('-') {
                '-'
            } else {
                return Ok(v);
            };
            let w = self.term()?;
            v = arith(op, v, w).map_err(|e| format!("line {line}: {e}"))?;
        }
    }

    fn term(&mut self) -> Result<Value, String> {
        let mut v = self.factor()?;
        loop {
            let line = self.line();
            let op = if self.eat_sym('*') {
                '*'
            } else if self.eat_sym('/') {
                '/'
            } else {
                return Ok(v);
            };
            let w = self.factor()?;
            v = arith(op, v, w).map_err(|e| format!("line {line}: {e}"))?;
        }
    }

    fn factor(&mut self) -> Result<Value, String> {
        let line = self.line();
        match self.peek().cloned() {
            Some(Tok::Sym('-')) => {
                self.pos += 1;
                let v = self.factor()?;
                arith('*', Value::Num(-1.0), v).map_err(|e| format!("line {line}: {e}"))
            }
            Some(Tok::Sym('+')) => {
                self.pos += 1;
                self.factor()
            }
            Some(Tok::Num(x)) => {
                self.pos += 1;
                Ok(Value::Num(x))
            }
            Some(Tok::Str(s)) => {
                self.pos += 1;
                Ok(Value::Str(s))
            }
            Some(Tok::Sym('(')) => {
                self.pos += 1;
                let v = self.expr()?;
                self.expect_sym(')')?;
                Ok(v)
            }
            Some(Tok::Sym('{')) => {
                self.pos += 1;
                let mut items = Vec::new();
                if !self.eat_sym('}') {
                    loop {
                        let at = self.line();
                        match self.expr()? {
                            Value::Num(x) => items.push(x),
                            other => return Err(format!("line {at}: only numbers are supported in an array, found {other}")),
                        }
                        if self.eat_sym('}') {
                            break;
                        }
                        if !self.eat_sym(',') {
                            return Err(self.err("`,` or `}` in an array"));
                        }
                    }
                }
                Ok(Value::Vec(items))
            }
            Some(Tok::Ident(s)) if s == "true" || s == "false" => {
                self.pos += 1;
                Ok(Value::Bool(s == "true"))
            }
            Some(Tok::Ident(_)) => {
                let name = self.dotted("a name")?;
                if self.is_sym('(') || self.is_sym('[') {
                    return Err(format!("line {line}: function calls and subscripts are not supported (`{name}`)"));
                }
                Ok(Value::Ident(name))
            }
            _ => Err(self.err("an expression")),
        }
    }

    /// `a.b` as in a connect equation.
    fn connector_ref(&mut self) -> Result<String, String> {
        let r = self.dotted("a connector reference")?;
        if self.is_sym('[') {
            return Err(format!("line {}: subscripts in connect are not supported", self.line()));
        }
        Ok(r)
    }
}

fn arith(op: char, a: Value, b: Value) -> Result<Value, String> {
    let f = |x: f64, y: f64| match op {
        '+' => x + y,
        '-' => x - y,
        '*' => x * y,
        _ => x / y,
    };
    match (a, b) {
        (Value::Num(x), Value::Num(y)) => Ok(Value::Num(f(x, y))),
        (Value::Vec(u), Value::Vec(v)) if (op == '+' || op == '-') && u.len() == v.len() => {
            Ok(Value::Vec(u.iter().zip(&v).map(|(x, y)| f(*x, *y)).collect()))
        }
        (Value::Num(x), Value::Vec(v)) if op == '*' => Ok(Value::Vec(v.iter().map(|y| x * y).collect())),
        (Value::Vec(v), Value::Num(y)) if op == '*' || op == '/' => Ok(Value::Vec(v.iter().map(|x| f(*x, y)).collect())),
        (a, b) => Err(format!("unsupported operation {a} {op} {b}")),
    }
}

/// Parses the text of a `Mechanics.mo` (one model, optionally `within PKG;`).
pub fn parse_mechanics(text: &str) -> Result<Model, String> {
    let toks = tokenize(text)?;
    let last_line = text.lines().count().max(1);
    let mut p = Parser { toks, pos: 0, last_line };

    let mut package = String::new();
    if p.eat_kw("within") {
        if !p.is_sym(';') {
            package = p.dotted("a package name")?;
        }
        p.expect_sym(';')?;
    }
    while p.eat_kw("encapsulated") || p.eat_kw("partial") {}
    if !(p.eat_kw("model") || p.eat_kw("class") || p.eat_kw("block")) {
        return Err(p.err("`model`"));
    }
    let model_name = p.ident("the model name")?;
    p.description()?;

    let mut components: Vec<Component> = Vec::new();
    let mut connects = Vec::new();
    let mut in_equations = false;
    loop {
        let line = p.line();
        if p.eat_kw("end") {
            let end_name = p.ident("the model name after `end`")?;
            if end_name != model_name {
                return Err(format!("line {line}: `end {end_name}` closes model `{model_name}`"));
            }
            p.expect_sym(';')?;
            if p.peek().is_some() {
                return Err(format!("line {}: unexpected {} after the end of the model", p.line(), p.describe_next()));
            }
            break;
        }
        if p.peek().is_none() {
            return Err(format!("line {line}: end of file before `end {model_name};`"));
        }
        if p.is_kw("annotation") {
            p.annotation()?;
            p.expect_sym(';')?;
            continue;
        }
        if p.eat_kw("equation") {
            in_equations = true;
            continue;
        }
        if p.eat_kw("public") || p.eat_kw("protected") {
            if in_equations {
                return Err(format!("line {line}: declarations after `equation` are not supported"));
            }
            continue;
        }
        if in_equations {
            if !p.eat_kw("connect") {
                return Err(p.err("`connect(...)` or `end` in the equation section"));
            }
            p.expect_sym('(')?;
            let a = p.connector_ref()?;
            p.expect_sym(',')?;
            let b = p.connector_ref()?;
            p.expect_sym(')')?;
            p.description()?;
            p.annotation()?;
            p.expect_sym(';')?;
            connects.push((a, b));
            continue;
        }
        for kw in ["extends", "import", "algorithm", "initial", "redeclare", "connector", "function", "model"] {
            if p.is_kw(kw) {
                return Err(format!("line {line}: `{kw}` is not supported in Mechanics.mo"));
            }
        }
        while PREFIXES.iter().any(|kw| p.eat_kw(kw)) {}
        let class = p.dotted("a type name")?;
        if p.is_sym('[') {
            return Err(format!("line {}: array declarations are not supported", p.line()));
        }
        let name_line = p.line();
        let name = p.ident(&format!("a component name after type `{class}`"))?;
        if p.is_sym('[') {
            return Err(format!("line {}: array declarations are not supported", p.line()));
        }
        let mut params = BTreeMap::new();
        if p.eat_sym('(') {
            p.modification("", &mut params)?;
        }
        if p.is_sym('=') {
            return Err(format!("line {}: a binding equation on component `{name}` is not supported", p.line()));
        }
        p.description()?;
        p.annotation()?;
        if p.is_sym(',') {
            return Err(format!("line {}: several components in one declaration are not supported", p.line()));
        }
        p.expect_sym(';')?;
        if components.iter().any(|c| c.name == name) {
            return Err(format!("line {name_line}: component `{name}` declared twice"));
        }
        components.push(Component { class, name, params });
    }
    Ok(Model { package, components, connects })
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLACE: &str = "annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})))";

    fn parse(text: &str) -> Model {
        match parse_mechanics(text) {
            Ok(m) => m,
            Err(e) => panic!("parse failed: {e}\n{text}"),
        }
    }

    fn wrap(body: &str, equations: &str) -> String {
        format!(
            "within Demo;\nmodel Mechanics \"Mechanical model of demo (1 bodies, 0 joints)\"\n{body}\nequation\n{equations}  annotation (\n    experiment(StopTime=1),\n    Documentation(info=\"<html>\n<p>Converted by cad2mo 0.1.0 from <code>a.xml</code>.</p>\n</html>\"));\nend Mechanics;\n"
        )
    }

    #[test]
    fn emitted_style_declarations_and_connects() {
        let body = format!(
            "  inner Modelica.Mechanics.MultiBody.World world(n={{0.0, -1.0, 0.0}}, g=9.81) \"World frame: the CAD assembly's frame\"\n    {PLACE};\n\n  // Bodies: frame_a is each part's CS1 frame\n  Modelica.Mechanics.MultiBody.Parts.Body link1(\n    m=0.25,\n    r_CM={{0.1, -2.5e-5, 1e-7}},\n    I_11=0.001, I_22=3.0, I_33=1e-7,\n    I_21=0.0, I_31=-0.0001, I_32=0.0,\n    animation=false)\n    \"Part link \\\"one\\\" \\\\ (nodeID 1:2)\" {PLACE};\n  Modelica.Mechanics.MultiBody.Parts.FixedRotation link1_CS2(\n    r={{0.0, 0.5, 0.0}},\n    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,\n    n_x={{0.0, 1.0, 0.0}},\n    n_y={{-1.0, 0.0, 0.0}},\n    animation=false)\n    \"Frame CS2 of link (nodeID 1:2)\" {PLACE};\n  Demo.Components.Revolute J1(\n    n={{0.0, 0.0, 1.0}},\n    phi(start=0.5, fixed=true),\n    w(start=0, fixed=true))\n    \"Joint J1 (nodeID 3)\" {PLACE};\n  Demo.Components.Prismatic J2(\n    n={{1.0, 0.0, 0.0}},\n    s(start=-0.25),\n    v(start=0))\n    \"Joint J2 (nodeID 4)\" {PLACE};\n  Modelica.Mechanics.MultiBody.Joints.Spherical J3(\n    enforceStates=true,\n    useQuaternions=true,\n    angles_fixed=true,\n    w_rel_a_fixed=true)\n    \"Joint J3 (nodeID 5)\" {PLACE};\n  Modelica.Mechanics.MultiBody.Joints.Spherical J4\n    \"Joint J4 (nodeID 6)\" {PLACE};\n  Modelica.Mechanics.MultiBody.Visualizers.FixedShape link1_shape(\n    shapeType=\"modelica://Demo/Resources/Shapes/link1.dxf\",\n    length=1, width=1, height=1,\n    extra=0,\n    color={{178, 178, 178}})\n    \"Shape of link\" {PLACE};"
        );
        let eqs = "  connect(world.frame_b, link1.frame_a);\n  connect(link1.frame_a, link1_CS2.frame_a);\n  connect(link1.frame_a, link1_shape.frame_a);\n";
        let m = parse(&wrap(&body, eqs));
        assert_eq!(m.package, "Demo");
        let names: Vec<&str> = m.components.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["world", "link1", "link1_CS2", "J1", "J2", "J3", "J4", "link1_shape"]);

        let world = m.component("world").expect("world");
        assert_eq!(world.class, "Modelica.Mechanics.MultiBody.World");
        assert_eq!(world.params["n"], Value::Vec(vec![0.0, -1.0, 0.0]));
        assert_eq!(world.num("g"), Some(9.81));

        let link = m.component("link1").expect("link1");
        assert_eq!(link.class, "Modelica.Mechanics.MultiBody.Parts.Body");
        assert_eq!(link.num("m"), Some(0.25));
        assert_eq!(link.vector("r_CM"), Some(&[0.1, -2.5e-5, 1e-7][..]));
        assert_eq!(link.num("I_22"), Some(3.0));
        assert_eq!(link.num("I_33"), Some(1e-7));
        assert_eq!(link.num("I_31"), Some(-0.0001));
        assert_eq!(link.params["animation"], Value::Bool(false));
        assert_eq!(link.params.len(), 9);

        let fr = m.component("link1_CS2").expect("frame");
        assert_eq!(fr.params["rotationType"], Value::Ident("Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors".into()));
        assert_eq!(fr.vector("n_y"), Some(&[-1.0, 0.0, 0.0][..]));

        let j1 = m.component("J1").expect("J1");
        assert_eq!(j1.class, "Demo.Components.Revolute");
        assert_eq!(j1.num("phi.start"), Some(0.5));
        assert_eq!(j1.params["phi.fixed"], Value::Bool(true));
        assert_eq!(j1.num("w.start"), Some(0.0));
        assert!(!j1.params.contains_key("phi"));

        let j2 = m.component("J2").expect("J2");
        assert_eq!(j2.num("s.start"), Some(-0.25));
        assert!(!j2.params.contains_key("s.fixed"));

        assert_eq!(m.component("J3").expect("J3").params["enforceStates"], Value::Bool(true));
        assert!(m.component("J4").expect("J4").params.is_empty());
        assert_eq!(m.component("J4").expect("J4").class, "Modelica.Mechanics.MultiBody.Joints.Spherical");

        let shape = m.component("link1_shape").expect("shape");
        assert_eq!(shape.string("shapeType"), Some("modelica://Demo/Resources/Shapes/link1.dxf"));
        assert_eq!(shape.vector("color"), Some(&[178.0, 178.0, 178.0][..]));
        assert_eq!(m.of_class("Modelica.Mechanics.MultiBody.Joints.Spherical").count(), 2);

        assert_eq!(
            m.connects,
            [
                ("world.frame_b".to_string(), "link1.frame_a".to_string()),
                ("link1.frame_a".to_string(), "link1_CS2.frame_a".to_string()),
                ("link1.frame_a".to_string(), "link1_shape.frame_a".to_string()),
            ]
        );
    }

    #[test]
    fn comments_strings_and_annotations_are_skipped() {
        let text = r#"within Demo.Sub; // a trailing comment
/* a block comment
   over lines, with "quotes" and connect(a.b, c.d); */
model Mechanics "desc with // not a comment and /* not either */"
  inner Modelica.Mechanics.MultiBody.World world /* inline */ "World" annotation (Placement(transformation(
      extent={{-10,-10},{10,10}}, origin={-160,0})));
  // Joints: a comment line with "a string" and ; semicolons
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation g( // comment inside
    r={1e+2, -0.0, 2E-3}, /* between */ animation=false)
    "escaped \"quote\", backslash \\, tab\t" + " joined";
equation
  connect(world.frame_b, g.frame_a) annotation (Line(points={{0,0},{1,1}}, color={95,95,95}));
  connect(g.frame_b, /* odd */ world.frame_b);
  annotation (Documentation(info="<html>
<p>multi-line; \"quoted\" text with connect(x.y, z.w);</p>
</html>"));
end Mechanics;
"#;
        let m = parse(text);
        assert_eq!(m.package, "Demo.Sub");
        assert_eq!(m.components.len(), 2);
        let g = m.component("g").expect("g");
        assert_eq!(g.vector("r"), Some(&[100.0, 0.0, 0.002][..]));
        assert_eq!(m.connects.len(), 2);
        assert_eq!(m.connects[1], ("g.frame_b".to_string(), "world.frame_b".to_string()));
    }

    #[test]
    fn escaped_string_values_are_decoded() {
        let text = "within P;\nmodel M\n  Foo.Bar x(s=\"a \\\"b\\\" \\\\ c\\n\", t=\"\", a=-(1.5), b=2*{1, -2, 3}/4, c={}, d=true);\nequation\nend M;\n";
        let m = parse(text);
        let x = m.component("x").expect("x");
        assert_eq!(x.string("s"), Some("a \"b\" \\ c\n"));
        assert_eq!(x.string("t"), Some(""));
        assert_eq!(x.num("a"), Some(-1.5));
        assert_eq!(x.vector("b"), Some(&[0.5, -1.0, 1.5][..]));
        assert_eq!(x.vector("c"), Some(&[][..]));
        assert_eq!(x.params["d"], Value::Bool(true));
    }

    #[test]
    fn nested_and_dotted_modifiers() {
        let text =
            "within ;\nmodel M\n  A b(phi(start=1, fixed=false, displayUnit=\"deg\"), s.start=2, x(y(z=3)), each final k=4);\nend M;\n";
        let m = parse(text);
        assert_eq!(m.package, "");
        let b = m.component("b").expect("b");
        assert_eq!(b.num("phi.start"), Some(1.0));
        assert_eq!(b.params["phi.fixed"], Value::Bool(false));
        assert_eq!(b.string("phi.displayUnit"), Some("deg"));
        assert_eq!(b.num("s.start"), Some(2.0));
        assert_eq!(b.num("x.y.z"), Some(3.0));
        assert_eq!(b.num("k"), Some(4.0));
        assert!(m.connects.is_empty());
    }

    fn error_of(text: &str) -> String {
        match parse_mechanics(text) {
            Ok(m) => panic!("expected an error, parsed {m:?}"),
            Err(e) => e,
        }
    }

    #[test]
    fn errors_name_the_line_and_the_problem() {
        // Missing semicolon after a multi-line declaration: reported where the next one starts.
        let e = error_of("within P;\nmodel M\n  A a(\n    r={1, 2, 3})\n    \"desc\"\n  B b;\nend M;\n");
        assert!(e.starts_with("line 6:") && e.contains("`;`") && e.contains("`B`"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a(r={1, 2, 3}) \"desc\n  ;\nend M;\n");
        assert!(e.starts_with("line 3:") && e.contains("unterminated string"), "{e}");

        let e = error_of("within P;\nmodel M\n  /* never closed\nend M;\n");
        assert!(e.starts_with("line 3:") && e.contains("unterminated /*"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a(r=@);\nend M;\n");
        assert!(e.starts_with("line 3:") && e.contains("'@'"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a;\nend N;\n");
        assert!(e.starts_with("line 4:") && e.contains("end N"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a(r=1, r=2);\nend M;\n");
        assert!(e.starts_with("line 3:") && e.contains("`r` given twice"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a;\n  A a;\nend M;\n");
        assert!(e.starts_with("line 4:") && e.contains("declared twice"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a;\nequation\n  connect(a.frame_a b.frame_b);\nend M;\n");
        assert!(e.starts_with("line 5:") && e.contains("`,`"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a;\nequation\n  x = 1;\nend M;\n");
        assert!(e.starts_with("line 5:") && e.contains("connect"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a(r={1, \"x\"});\nend M;\n");
        assert!(e.starts_with("line 3:") && e.contains("only numbers"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a(r=1.5e);\nend M;\n");
        assert!(e.starts_with("line 3:") && e.contains("exponent"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a;\n");
        assert!(e.contains("end of file"), "{e}");

        let e = error_of("within P;\nmodel M\n  A a;\nend M;\nB b;\n");
        assert!(e.starts_with("line 5:") && e.contains("after the end"), "{e}");
    }
}
