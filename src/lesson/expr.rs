//! Lesson expressions: `restitution < 0.6`, `within(contact_duration_s, 2*bar1.length/c1, 0.05)`.
//!
//! Parsed once when the lesson loads, checked against the scene's vocabulary (an unknown name is
//! an error then, not a false at run time), evaluated against a [`Context`] of the live result.
//!
//! Grammar, loosest first: `or`, `and`, `not`, comparisons (`< <= > >= == !=`), `+ -`,
//! `* /`, unary `-`, `^` (right-associative), then numbers (`1e-3`), strings (`"sears"`),
//! `true`/`false`, names (letters, digits, `_` and `.`: `bar1.length`, `wave.restitution`),
//! calls `abs min max sqrt ln exp within(x, y, frac)` and parentheses.

use super::context::{Context, Vocabulary};
use std::fmt;

/// A value an expression yields.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Number(f64),
    Bool(bool),
    Text(String),
}

impl Value {
    fn kind(&self) -> &'static str {
        match self {
            Value::Number(_) => "a number",
            Value::Bool(_) => "true/false",
            Value::Text(_) => "a word",
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Number(x) => write!(f, "{}", crate::model::settings::shown(*x)),
            Value::Bool(b) => write!(f, "{b}"),
            Value::Text(s) => write!(f, "\"{s}\""),
        }
    }
}

/// Why an expression could not be parsed, checked or evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExprError {
    #[error("cannot read the expression at character {at}: {message}")]
    Syntax { at: usize, message: String },
    #[error("unknown name '{name}'{hint}")]
    UnknownName { name: String, hint: String },
    #[error("'{name}' has no value in this run ({why})")]
    Unavailable { name: String, why: String },
    #[error("{0}")]
    Type(String),
    #[error("unknown function '{0}': allowed abs, min, max, sqrt, ln, exp, within")]
    UnknownFunction(String),
    #[error("the result is not a finite number ({0})")]
    NotFinite(String),
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
}

/// A parsed expression, with its source text.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    pub source: String,
    node: Node,
}

#[derive(Debug, Clone, PartialEq)]
enum Node {
    Num(f64),
    Bool(bool),
    Text(String),
    Name(String),
    Neg(Box<Node>),
    Not(Box<Node>),
    Bin(BinOp, Box<Node>, Box<Node>),
    Call(String, Vec<Node>),
}

const FUNCTIONS: &[(&str, usize)] = &[
    ("abs", 1),
    ("sqrt", 1),
    ("ln", 1),
    ("exp", 1),
    ("min", 2),
    ("max", 2),
    ("within", 3),
];

impl Expr {
    /// Parses `text`; names are not checked here (see [`Expr::check`]).
    pub fn parse(text: &str) -> Result<Expr, ExprError> {
        let mut p = Parser {
            chars: text.char_indices().collect(),
            pos: 0,
            depth: 0,
        };
        let node = p.or()?;
        p.skip_ws();
        if p.pos < p.chars.len() {
            return Err(p.error("unexpected text after the expression"));
        }
        Ok(Expr {
            source: text.to_string(),
            node,
        })
    }

    /// Every name the expression reads.
    pub fn names(&self) -> Vec<&str> {
        let mut out = Vec::new();
        collect_names(&self.node, &mut out);
        out
    }

    /// Refuses names the vocabulary does not know and calls with the wrong argument count.
    pub fn check(&self, vocabulary: &Vocabulary) -> Result<(), ExprError> {
        for name in self.names() {
            if !vocabulary.knows(name) {
                return Err(ExprError::UnknownName {
                    name: name.to_string(),
                    hint: vocabulary.hint(name),
                });
            }
        }
        check_calls(&self.node)
    }

    /// The expression's value for a run.
    pub fn eval(&self, ctx: &Context) -> Result<Value, ExprError> {
        eval(&self.node, ctx)
    }

    /// The value as a number (a prediction's answer).
    pub fn number(&self, ctx: &Context) -> Result<f64, ExprError> {
        match self.eval(ctx)? {
            Value::Number(x) if x.is_finite() => Ok(x),
            Value::Number(x) => Err(ExprError::NotFinite(format!("{x}"))),
            other => Err(ExprError::Type(format!(
                "expected a number, got {}",
                other.kind()
            ))),
        }
    }

    /// The value as true/false (a task's goal).
    pub fn truth(&self, ctx: &Context) -> Result<bool, ExprError> {
        match self.eval(ctx)? {
            Value::Bool(b) => Ok(b),
            other => Err(ExprError::Type(format!(
                "expected true/false (a comparison), got {}",
                other.kind()
            ))),
        }
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.source)
    }
}

fn collect_names<'a>(node: &'a Node, out: &mut Vec<&'a str>) {
    match node {
        Node::Name(n) => out.push(n),
        Node::Neg(a) | Node::Not(a) => collect_names(a, out),
        Node::Bin(_, a, b) => {
            collect_names(a, out);
            collect_names(b, out);
        }
        Node::Call(_, args) => args.iter().for_each(|a| collect_names(a, out)),
        Node::Num(_) | Node::Bool(_) | Node::Text(_) => {}
    }
}

fn check_calls(node: &Node) -> Result<(), ExprError> {
    match node {
        Node::Call(name, args) => {
            let Some((_, arity)) = FUNCTIONS.iter().find(|(n, _)| n == name) else {
                return Err(ExprError::UnknownFunction(name.clone()));
            };
            if args.len() != *arity {
                return Err(ExprError::Type(format!(
                    "{name} takes {arity} argument(s), got {}",
                    args.len()
                )));
            }
            args.iter().try_for_each(check_calls)
        }
        Node::Neg(a) | Node::Not(a) => check_calls(a),
        Node::Bin(_, a, b) => check_calls(a).and_then(|()| check_calls(b)),
        Node::Num(_) | Node::Bool(_) | Node::Text(_) | Node::Name(_) => Ok(()),
    }
}

fn num(v: Value, what: &str) -> Result<f64, ExprError> {
    match v {
        Value::Number(x) => Ok(x),
        other => Err(ExprError::Type(format!(
            "{what} needs a number, got {}",
            other.kind()
        ))),
    }
}

fn boolean(v: Value, what: &str) -> Result<bool, ExprError> {
    match v {
        Value::Bool(b) => Ok(b),
        other => Err(ExprError::Type(format!(
            "{what} needs true/false, got {}",
            other.kind()
        ))),
    }
}

fn eval(node: &Node, ctx: &Context) -> Result<Value, ExprError> {
    Ok(match node {
        Node::Num(x) => Value::Number(*x),
        Node::Bool(b) => Value::Bool(*b),
        Node::Text(s) => Value::Text(s.clone()),
        Node::Name(n) => ctx.get(n)?,
        Node::Neg(a) => Value::Number(-num(eval(a, ctx)?, "-")?),
        Node::Not(a) => Value::Bool(!boolean(eval(a, ctx)?, "not")?),
        Node::Bin(op, a, b) => binary(*op, eval(a, ctx)?, || eval(b, ctx))?,
        Node::Call(name, args) => {
            let xs = args
                .iter()
                .map(|a| eval(a, ctx).and_then(|v| num(v, name)))
                .collect::<Result<Vec<f64>, _>>()?;
            call(name, &xs)?
        }
    })
}

fn call(name: &str, xs: &[f64]) -> Result<Value, ExprError> {
    let arity = |n: usize| {
        if xs.len() == n {
            Ok(())
        } else {
            Err(ExprError::Type(format!(
                "{name} takes {n} argument(s), got {}",
                xs.len()
            )))
        }
    };
    let v = match name {
        "abs" | "sqrt" | "ln" | "exp" => {
            arity(1)?;
            match name {
                "abs" => xs[0].abs(),
                "sqrt" => xs[0].sqrt(),
                "ln" => xs[0].ln(),
                _ => xs[0].exp(),
            }
        }
        "min" | "max" => {
            arity(2)?;
            if name == "min" {
                xs[0].min(xs[1])
            } else {
                xs[0].max(xs[1])
            }
        }
        "within" => {
            arity(3)?;
            return Ok(Value::Bool(within(xs[0], xs[1], xs[2])));
        }
        other => return Err(ExprError::UnknownFunction(other.to_string())),
    };
    if v.is_finite() {
        Ok(Value::Number(v))
    } else {
        Err(ExprError::NotFinite(format!("{name} of {xs:?}")))
    }
}

/// Whether `x` lies within `frac` of `y`, relatively: |x - y| <= frac |y|.
pub fn within(x: f64, y: f64, frac: f64) -> bool {
    (x - y).abs() <= frac * y.abs()
}

fn binary(
    op: BinOp,
    a: Value,
    b: impl FnOnce() -> Result<Value, ExprError>,
) -> Result<Value, ExprError> {
    use BinOp::*;
    // `and`/`or` short-circuit, so `impact_count > 0 and x / impact_count < 1` is safe.
    match op {
        And => {
            return Ok(Value::Bool(boolean(a, "and")? && boolean(b()?, "and")?));
        }
        Or => return Ok(Value::Bool(boolean(a, "or")? || boolean(b()?, "or")?)),
        _ => {}
    }
    let b = b()?;
    if matches!(op, Eq | Ne) {
        let same = match (&a, &b) {
            (Value::Number(x), Value::Number(y)) => x == y,
            (Value::Bool(x), Value::Bool(y)) => x == y,
            (Value::Text(x), Value::Text(y)) => x == y,
            _ => {
                return Err(ExprError::Type(format!(
                    "cannot compare {} with {}",
                    a.kind(),
                    b.kind()
                )));
            }
        };
        return Ok(Value::Bool(same == (op == Eq)));
    }
    let (x, y) = (num(a, "arithmetic")?, num(b, "arithmetic")?);
    let v = match op {
        Lt => return Ok(Value::Bool(x < y)),
        Le => return Ok(Value::Bool(x <= y)),
        Gt => return Ok(Value::Bool(x > y)),
        Ge => return Ok(Value::Bool(x >= y)),
        Add => x + y,
        Sub => x - y,
        Mul => x * y,
        Div => x / y,
        Pow => x.powf(y),
        Eq | Ne | And | Or => unreachable!("handled above"),
    };
    if v.is_finite() {
        Ok(Value::Number(v))
    } else {
        Err(ExprError::NotFinite(format!("{x} {op:?} {y}")))
    }
}

/// How deep an expression may nest: each bracket, `not`, unary minus, `^` and function call,
/// and each further term of a chain (`a + b + c`, `a and b and c`), is one level. Evaluating,
/// checking and dropping a tree walk it recursively, so a bound keeps a hostile file from
/// overflowing the stack; a lesson's statements nest a few levels.
pub const MAX_DEPTH: usize = 256;

struct Parser {
    chars: Vec<(usize, char)>,
    pos: usize,
    /// How deep the node being parsed sits in the tree (an upper bound).
    depth: usize,
}

impl Parser {
    fn error(&self, message: &str) -> ExprError {
        ExprError::Syntax {
            at: self.pos + 1,
            message: message.to_string(),
        }
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).map(|(_, c)| *c)
    }

    /// One level deeper, refused past [`MAX_DEPTH`].
    fn deeper(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.error(&format!(
                "the expression nests more than {MAX_DEPTH} deep (brackets, not, minus, ^, calls \
                 and the terms of a chain each count one)"
            )));
        }
        Ok(())
    }

    /// Parses with `parse` one level deeper, then comes back.
    fn nested(
        &mut self,
        parse: impl FnOnce(&mut Self) -> Result<Node, ExprError>,
    ) -> Result<Node, ExprError> {
        self.deeper()?;
        let node = parse(self)?;
        self.depth -= 1;
        Ok(node)
    }

    fn skip_ws(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.pos += 1;
        }
    }

    /// Consumes `token` (a symbol, or a keyword not followed by a name character).
    fn eat(&mut self, token: &str) -> bool {
        self.skip_ws();
        let n = token.chars().count();
        let matches = token
            .chars()
            .enumerate()
            .all(|(i, c)| self.chars.get(self.pos + i).map(|(_, d)| *d) == Some(c));
        let word = token.chars().all(|c| c.is_ascii_alphabetic());
        let after_is_name = self
            .chars
            .get(self.pos + n)
            .is_some_and(|(_, c)| is_name_char(*c));
        if matches && !(word && after_is_name) {
            self.pos += n;
            true
        } else {
            false
        }
    }

    /// A left-associative chain: `first`, then `next` after each operator `op` finds; the tree
    /// deepens by one a term.
    fn chain(
        &mut self,
        first: fn(&mut Self) -> Result<Node, ExprError>,
        op: fn(&mut Self) -> Option<BinOp>,
    ) -> Result<Node, ExprError> {
        let base = self.depth;
        let mut left = first(self)?;
        while let Some(op) = op(self) {
            self.deeper()?;
            left = Node::Bin(op, Box::new(left), Box::new(first(self)?));
        }
        self.depth = base;
        Ok(left)
    }

    fn or(&mut self) -> Result<Node, ExprError> {
        self.chain(Self::and, |p| p.eat("or").then_some(BinOp::Or))
    }

    fn and(&mut self) -> Result<Node, ExprError> {
        self.chain(Self::not, |p| p.eat("and").then_some(BinOp::And))
    }

    fn not(&mut self) -> Result<Node, ExprError> {
        if self.eat("not") {
            return Ok(Node::Not(Box::new(self.nested(Self::not)?)));
        }
        self.comparison()
    }

    fn comparison(&mut self) -> Result<Node, ExprError> {
        let left = self.sum()?;
        for (token, op) in [
            ("<=", BinOp::Le),
            (">=", BinOp::Ge),
            ("==", BinOp::Eq),
            ("!=", BinOp::Ne),
            ("<", BinOp::Lt),
            (">", BinOp::Gt),
        ] {
            if self.eat(token) {
                return Ok(Node::Bin(
                    op,
                    Box::new(left),
                    Box::new(self.nested(Self::sum)?),
                ));
            }
        }
        Ok(left)
    }

    fn sum(&mut self) -> Result<Node, ExprError> {
        self.chain(Self::product, |p| {
            if p.eat("+") {
                Some(BinOp::Add)
            } else if p.eat("-") {
                Some(BinOp::Sub)
            } else {
                None
            }
        })
    }

    fn product(&mut self) -> Result<Node, ExprError> {
        self.chain(Self::unary, |p| {
            if p.eat("*") {
                Some(BinOp::Mul)
            } else if p.eat("/") {
                Some(BinOp::Div)
            } else {
                None
            }
        })
    }

    fn unary(&mut self) -> Result<Node, ExprError> {
        if self.eat("-") {
            return Ok(Node::Neg(Box::new(self.nested(Self::unary)?)));
        }
        self.power()
    }

    fn power(&mut self) -> Result<Node, ExprError> {
        let base = self.atom()?;
        if self.eat("^") {
            // Right-associative, and binding tighter than a unary minus on its left: -2^2 = -4.
            return Ok(Node::Bin(
                BinOp::Pow,
                Box::new(base),
                Box::new(self.nested(Self::unary)?),
            ));
        }
        Ok(base)
    }

    fn atom(&mut self) -> Result<Node, ExprError> {
        self.skip_ws();
        match self.peek() {
            None => Err(self.error("the expression ends too early")),
            Some('(') => {
                self.pos += 1;
                let inner = self.nested(Self::or)?;
                if !self.eat(")") {
                    return Err(self.error("expected ')'"));
                }
                Ok(inner)
            }
            Some('"') => self.string(),
            Some(c) if c.is_ascii_digit() || c == '.' => self.number(),
            Some(c) if c.is_ascii_alphabetic() || c == '_' => self.name_or_call(),
            Some(c) => Err(self.error(&format!("unexpected '{c}'"))),
        }
    }

    fn string(&mut self) -> Result<Node, ExprError> {
        self.pos += 1;
        let start = self.pos;
        while self.peek().is_some_and(|c| c != '"') {
            self.pos += 1;
        }
        if self.peek().is_none() {
            return Err(self.error("a string without its closing '\"'"));
        }
        let text: String = self.chars[start..self.pos].iter().map(|(_, c)| c).collect();
        self.pos += 1;
        Ok(Node::Text(text))
    }

    fn number(&mut self) -> Result<Node, ExprError> {
        let start = self.pos;
        let digits = |p: &mut Parser| {
            while p.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
                p.pos += 1;
            }
        };
        digits(self);
        if matches!(self.peek(), Some('e' | 'E')) {
            let save = self.pos;
            self.pos += 1;
            if matches!(self.peek(), Some('+' | '-')) {
                self.pos += 1;
            }
            if self.peek().is_some_and(|c| c.is_ascii_digit()) {
                digits(self);
            } else {
                self.pos = save;
            }
        }
        let text: String = self.chars[start..self.pos].iter().map(|(_, c)| c).collect();
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(Node::Num(x)),
            _ => {
                self.pos = start;
                Err(self.error(&format!("'{text}' is not a number")))
            }
        }
    }

    fn name_or_call(&mut self) -> Result<Node, ExprError> {
        let start = self.pos;
        while self.peek().is_some_and(is_name_char) {
            self.pos += 1;
        }
        let name: String = self.chars[start..self.pos].iter().map(|(_, c)| c).collect();
        if name.ends_with('.') {
            return Err(self.error(&format!("'{name}' ends with a '.'")));
        }
        match name.as_str() {
            "true" => return Ok(Node::Bool(true)),
            "false" => return Ok(Node::Bool(false)),
            "and" | "or" | "not" => {
                self.pos = start;
                return Err(self.error(&format!("'{name}' needs something before it")));
            }
            _ => {}
        }
        if self.eat("(") {
            let mut args = Vec::new();
            if !self.eat(")") {
                loop {
                    args.push(self.nested(Self::or)?);
                    if self.eat(")") {
                        break;
                    }
                    if !self.eat(",") {
                        return Err(self.error("expected ',' or ')' in the call"));
                    }
                }
            }
            return Ok(Node::Call(name, args));
        }
        Ok(Node::Name(name))
    }
}

fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '.'
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(text: &str) -> Value {
        Expr::parse(text).unwrap().eval(&Context::empty()).unwrap()
    }

    #[test]
    fn precedence_follows_arithmetic() {
        assert_eq!(value("1 + 2 * 3 ^ 2"), Value::Number(19.0));
        assert_eq!(value("-2 ^ 2"), Value::Number(-4.0));
        assert_eq!(value("2 ^ 3 ^ 2"), Value::Number(512.0));
        assert_eq!(value("(1 + 2) * 3"), Value::Number(9.0));
        assert_eq!(value("1e-3 * 2e3"), Value::Number(2.0));
    }

    #[test]
    fn logic_and_comparisons_combine() {
        assert_eq!(value("1 < 2 and not 3 <= 2"), Value::Bool(true));
        assert_eq!(value("1 > 2 or 2 == 2"), Value::Bool(true));
        assert_eq!(value("within(1.04, 1, 0.05)"), Value::Bool(true));
        assert_eq!(value("within(1.06, 1, 0.05)"), Value::Bool(false));
        assert_eq!(value("\"a\" != \"b\""), Value::Bool(true));
    }

    #[test]
    fn malformed_text_is_an_error_with_a_position() {
        for bad in ["1 +", "(1", "1 2", "abs(1", "and 1", "x.", "\"a", "1 < < 2"] {
            assert!(
                matches!(Expr::parse(bad), Err(ExprError::Syntax { .. })),
                "{bad}"
            );
        }
    }

    #[test]
    fn type_errors_and_division_by_zero_are_errors_not_values() {
        let ctx = Context::empty();
        for bad in ["1 / 0", "sqrt(-1)", "true + 1", "1 and true", "\"a\" < 1"] {
            assert!(Expr::parse(bad).unwrap().eval(&ctx).is_err(), "{bad}");
        }
    }

    #[test]
    fn nesting_past_the_limit_is_refused_and_below_it_evaluates() {
        let deep = MAX_DEPTH + 10;
        let refused = [
            format!("{}1{}", "(".repeat(deep), ")".repeat(deep)),
            format!("{}true", "not ".repeat(deep)),
            format!("{}1", "-".repeat(deep)),
            vec!["1"; deep].join(" + "),
            vec!["2"; deep].join(" * "),
            vec!["true"; deep].join(" and "),
            vec!["2"; deep].join(" ^ "),
            format!("{}1{}", "abs(".repeat(deep), ")".repeat(deep)),
        ];
        for text in &refused {
            match Expr::parse(text) {
                Err(ExprError::Syntax { message, .. }) => {
                    assert!(message.contains("nests more than"), "{message}")
                }
                other => panic!("{}...: {other:?}", &text[..20]),
            }
        }
        // Ten thousand deep: refused in the parse, not a stack overflow.
        assert!(Expr::parse(&format!("{}1", "-".repeat(10_000))).is_err());
        assert!(Expr::parse(&vec!["1"; 10_000].join(" + ")).is_err());
        // Just inside the limit, every form still evaluates.
        let inside = MAX_DEPTH - 2;
        assert_eq!(
            value(&format!("{}1{}", "(".repeat(inside), ")".repeat(inside))),
            Value::Number(1.0)
        );
        assert_eq!(
            value(&vec!["1"; inside].join(" + ")),
            Value::Number(inside as f64)
        );
        assert_eq!(
            value(&format!("{}1", "- ".repeat(inside))),
            Value::Number(1.0)
        );
    }
}
