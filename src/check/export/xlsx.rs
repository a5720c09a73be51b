//! `phong grade --format xlsx`: the grade workbook an instructor opens in Excel or LibreOffice
//! set to pt-BR, where a CSV splits wrongly and reads `0.5` as text. Three sheets, headers in
//! the report's language, the header row frozen and filtered:
//!
//! - the answers: one line per row of the submissions, in input order, with numbers stored as
//!   numbers (points, the expected colour, the differences, the tolerance) and the verdict in
//!   words, its cell coloured (and the word says it: colour is never the only signal);
//! - the students: each student's total, maximum and points per exercise (empty: no answer);
//! - the summary: per exercise, how many rows were right, by the reading, wrong and invalid,
//!   and the slips named, each with its count;
//! - the class: what the class got wrong, line by line as the class report says it
//!   (`export::class`).
//!
//! Text from the submissions goes through the one XML rule (`text::xml::sanitize`): a workbook
//! is XML inside, and a character XML forbids would make Excel refuse it.
//!
//! The answers' and the students' sheets are written row by row in the library's
//! constant-memory mode, so a class of a million rows stays within the grading's memory bound. The CSV stays the machine format.

use rust_xlsxwriter::{
    Color, DocProperties, ExcelDateTime, Format, Workbook, Worksheet, XlsxError,
};

use crate::check::grade::{Graded, RowOut};
use crate::text::xml::sanitize;
use crate::text::{Lang, Message};

crate::messages! {
    /// The words of the grade workbook.
    #[allow(missing_docs)]
    pub enum Sheet {
        Answers => "Answers", "Respostas";
        Students => "Students", "Alunos";
        Summary => "Summary", "Resumo";
        Row => "Row", "Linha do relatório";
        Line => "Line", "Linha do arquivo";
        Student => "Student", "Aluno";
        Exercise => "Exercise", "Exercício";
        Answer => "Answer", "Resposta";
        Verdict => "Verdict", "Veredito";
        Points => "Points", "Pontos";
        MaxPoints => "Maximum", "Máximo";
        Counted => "Counts", "Conta";
        Scale => "Scale", "Escala";
        Tolerance => "Tolerance", "Tolerância";
        ExpectedR => "Expected R", "Esperado R";
        ExpectedG => "Expected G", "Esperado G";
        ExpectedB => "Expected B", "Esperado B";
        DifferenceR => "Difference R", "Diferença R";
        DifferenceG => "Difference G", "Diferença G";
        DifferenceB => "Difference B", "Diferença B";
        Reading => "Reading", "Leitura";
        Slips => "Slips", "Erros";
        Feedback => "Feedback", "Comentário";
        Rows => "Answers", "Respostas";
        Right => "Right", "Certas";
        ByReading => "By the reading", "Pela leitura";
        Wrong => "Wrong", "Erradas";
        Invalid => "Invalid", "Inválidas";
        Yes => "yes", "sim";
        No => "no", "não";
        VerdictRight => "right", "certa";
        VerdictReading => "reading", "leitura";
        VerdictWrong => "wrong", "errada";
        VerdictInvalid => "invalid", "inválida";
    }
}

/// The verdict of a row in words, and its cell's colour (Excel's own "good", "neutral" and
/// "bad" fills).
fn verdict(code: &str) -> (Sheet, u32) {
    match code {
        "right" => (Sheet::VerdictRight, 0xC6EFCE),
        "reading" => (Sheet::VerdictReading, 0xFFEB9C),
        "wrong" => (Sheet::VerdictWrong, 0xFFC7CE),
        _ => (Sheet::VerdictInvalid, 0xD9D9D9),
    }
}

fn header(sheet: &mut Worksheet, words: &[Sheet], lang: Lang) -> Result<(), XlsxError> {
    let bold = Format::new().set_bold();
    for (c, w) in words.iter().enumerate() {
        sheet.write_string_with_format(0, c as u16, w.text(lang), &bold)?;
    }
    sheet.set_freeze_panes(1, 0)?;
    Ok(())
}

/// A row's slips, in words, `;` between the alternatives.
fn slips(row: &RowOut, lang: Lang) -> String {
    row.diagnosis
        .iter()
        .map(|d| crate::check::messages::slips(d, lang))
        .collect::<Vec<_>>()
        .join("; ")
}

fn answers(book: &mut Workbook, graded: &Graded, lang: Lang) -> Result<(), XlsxError> {
    let columns = [
        Sheet::Row,
        Sheet::Line,
        Sheet::Student,
        Sheet::Exercise,
        Sheet::Answer,
        Sheet::Verdict,
        Sheet::Points,
        Sheet::MaxPoints,
        Sheet::Counted,
        Sheet::Scale,
        Sheet::Tolerance,
        Sheet::ExpectedR,
        Sheet::ExpectedG,
        Sheet::ExpectedB,
        Sheet::DifferenceR,
        Sheet::DifferenceG,
        Sheet::DifferenceB,
        Sheet::Reading,
        Sheet::Slips,
        Sheet::Feedback,
    ];
    let sheet = book.add_worksheet_with_constant_memory();
    sheet.set_name(Sheet::Answers.text(lang))?;
    header(sheet, &columns, lang)?;
    let mut last = 0;
    for (i, row) in graded.rows().enumerate() {
        let r = i as u32 + 1;
        last = r;
        sheet.write_number(r, 0, row.row as f64)?;
        sheet.write_number(r, 1, row.line as f64)?;
        sheet.write_string(r, 2, sanitize(&row.student))?;
        sheet.write_string(r, 3, sanitize(&row.exercise))?;
        sheet.write_string(r, 4, sanitize(&row.answer))?;
        let (word, fill) = verdict(row.verdict);
        let coloured = Format::new().set_background_color(Color::RGB(fill));
        sheet.write_string_with_format(r, 5, word.text(lang), &coloured)?;
        sheet.write_number(r, 6, row.points)?;
        if let Some(m) = row.max_points {
            sheet.write_number(r, 7, m)?;
        }
        let counted = if row.counted { Sheet::Yes } else { Sheet::No };
        sheet.write_string(r, 8, counted.text(lang))?;
        if let Some(s) = row.scale {
            sheet.write_number(r, 9, f64::from(s))?;
        }
        if let Some(t) = row.tolerance {
            sheet.write_number(r, 10, t)?;
        }
        for (k, x) in row.expected.iter().flatten().enumerate() {
            sheet.write_number(r, 11 + k as u16, *x)?;
        }
        for (k, x) in row.difference.iter().flatten().enumerate() {
            sheet.write_number(r, 14 + k as u16, *x)?;
        }
        if let Some(code) = row.reading {
            sheet.write_string(r, 17, crate::check::messages::reading(code, lang))?;
        }
        let s = slips(&row, lang);
        if !s.is_empty() {
            sheet.write_string(r, 18, &s)?;
        }
        sheet.write_string(r, 19, sanitize(&row.feedback))?;
    }
    sheet.autofilter(0, 0, last, columns.len() as u16 - 1)?;
    Ok(())
}

fn students(book: &mut Workbook, graded: &Graded, lang: Lang) -> Result<(), XlsxError> {
    // A student a row, in order: constant memory too (a class file may hold a million).
    let sheet = book.add_worksheet_with_constant_memory();
    sheet.set_name(Sheet::Students.text(lang))?;
    header(
        sheet,
        &[Sheet::Student, Sheet::Points, Sheet::MaxPoints],
        lang,
    )?;
    let mut exercises: Vec<&String> = graded.exercises().keys().collect();
    exercises.sort_by(|a, b| crate::check::grade::natural_order(a, b));
    let bold = Format::new().set_bold();
    for (k, e) in exercises.iter().enumerate() {
        sheet.write_string_with_format(0, 3 + k as u16, sanitize(e), &bold)?;
    }
    let n = graded.students();
    for s in 0..n {
        let st = graded.student(s);
        let r = s as u32 + 1;
        sheet.write_string(r, 0, sanitize(&st.student))?;
        sheet.write_number(r, 1, st.points)?;
        sheet.write_number(r, 2, st.max_points)?;
        for (k, e) in exercises.iter().enumerate() {
            if let Some(Some(p)) = st.exercises.get(*e) {
                sheet.write_number(r, 3 + k as u16, *p)?;
            }
        }
    }
    sheet.autofilter(0, 0, n as u32, 2 + exercises.len() as u16)?;
    Ok(())
}

fn summary(book: &mut Workbook, graded: &Graded, lang: Lang) -> Result<(), XlsxError> {
    let sheet = book.add_worksheet();
    sheet.set_name(Sheet::Summary.text(lang))?;
    header(
        sheet,
        &[
            Sheet::Exercise,
            Sheet::Rows,
            Sheet::Right,
            Sheet::ByReading,
            Sheet::Wrong,
            Sheet::Invalid,
            Sheet::Slips,
        ],
        lang,
    )?;
    let rows = graded.summary();
    for (i, s) in rows.iter().enumerate() {
        let r = i as u32 + 1;
        sheet.write_string(r, 0, sanitize(&s.exercise))?;
        for (k, n) in [s.rows, s.right, s.reading, s.wrong, s.invalid]
            .iter()
            .enumerate()
        {
            sheet.write_number(r, 1 + k as u16, *n as f64)?;
        }
        let named: Vec<String> = s
            .slips
            .iter()
            .map(|c| {
                format!(
                    "{}: {}",
                    crate::check::messages::slips(&c.slips, lang),
                    c.count
                )
            })
            .collect();
        if !named.is_empty() {
            sheet.write_string(r, 6, named.join("; "))?;
        }
    }
    sheet.autofilter(0, 0, rows.len() as u32, 6)?;
    Ok(())
}

/// The class sheet: what the class got wrong, as the class report says it (`class::lines`).
fn class(book: &mut Workbook, graded: &Graded, lang: Lang) -> Result<(), XlsxError> {
    use super::class::ClassWords;
    let sheet = book.add_worksheet();
    sheet.set_name(ClassWords::Class.text(lang))?;
    let bold = Format::new().set_bold();
    for (c, w) in [ClassWords::Exercise, ClassWords::What, ClassWords::Answers]
        .iter()
        .enumerate()
    {
        sheet.write_string_with_format(0, c as u16, w.text(lang), &bold)?;
    }
    sheet.set_freeze_panes(1, 0)?;
    let lines = super::class::lines(graded, lang);
    for (i, l) in lines.iter().enumerate() {
        let r = i as u32 + 1;
        sheet.write_string(r, 0, sanitize(&l.exercise))?;
        sheet.write_string(r, 1, &l.what)?;
        sheet.write_number(r, 2, l.count as f64)?;
    }
    sheet.autofilter(0, 0, lines.len() as u32, 2)?;
    Ok(())
}

/// When a workbook says it was made, unless told otherwise: 1980-01-01 00:00 UTC, the time
/// its zip entries carry (the library pins them), as a Unix time.
pub const MADE: i64 = 315_532_800;

/// The workbook of a graded class, written to `w`, saying it was made at `made` (a Unix time,
/// 1970 to 9999: [`MADE`], or `SOURCE_DATE_EPOCH`), never at the time of the run: the same
/// class gives the same bytes.
pub fn write(
    graded: &Graded,
    lang: Lang,
    made: i64,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let mut book = Workbook::new();
    let made = ExcelDateTime::from_timestamp(made)
        .map_err(|e| std::io::Error::new(std::io::ErrorKind::InvalidInput, e.to_string()))?;
    book.set_properties(&DocProperties::new().set_creation_datetime(&made));
    let made = answers(&mut book, graded, lang)
        .and_then(|()| students(&mut book, graded, lang))
        .and_then(|()| summary(&mut book, graded, lang))
        .and_then(|()| class(&mut book, graded, lang))
        .and_then(|()| book.save_to_buffer());
    let bytes = made.map_err(|e| std::io::Error::other(e.to_string()))?;
    w.write_all(&bytes)
}
