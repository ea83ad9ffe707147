# SPDX-License-Identifier: GPL-3.0-or-later
"""Reading and writing a Qt Linguist catalogue (.ts) for the translation tools beside it.

A message is identified by its context (the class, e.g. "xyt::ui::MainWindow") and its source
text. Qt's lupdate rewrites the file in its own layout on the next refresh, so the layout written
here only has to be valid XML that lupdate and lrelease read.
"""
import re
import xml.etree.ElementTree as ET

PLACEHOLDER = re.compile(r"%(L?)(\d+|n)")
TAG = re.compile(r"</?([A-Za-z][A-Za-z0-9]*)\b")
ENTITY = re.compile(r"&(#\d+|#x[0-9A-Fa-f]+|[A-Za-z]+);")


def load(path):
    return ET.parse(path)


def messages(tree):
    """Yields (context name, message element) for every message of the catalogue."""
    for context in tree.getroot().iter("context"):
        name = context.findtext("name")
        for message in context.iter("message"):
            yield name, message


def source_of(message):
    return message.findtext("source") or ""


def is_plural(message):
    return message.get("numerus") == "yes"


def translations_of(message):
    """The translation's forms: one string, or the plural forms."""
    tr = message.find("translation")
    if tr is None:
        return []
    if is_plural(message):
        return [f.text or "" for f in tr.findall("numerusform")]
    return [tr.text or ""]


def state_of(message):
    tr = message.find("translation")
    return None if tr is None else tr.get("type")


def set_translation(message, value, plural_forms=2):
    """Sets the translation (a string, or a list of plural forms) and marks it finished."""
    tr = message.find("translation")
    if tr is None:
        tr = ET.SubElement(message, "translation")
    for child in list(tr):
        tr.remove(child)
    tr.text = None
    if "type" in tr.attrib:
        del tr.attrib["type"]
    if is_plural(message):
        forms = value if isinstance(value, (list, tuple)) else [value] * plural_forms
        for form in forms:
            ET.SubElement(tr, "numerusform").text = form
    else:
        if isinstance(value, (list, tuple)):
            raise ValueError("a plural translation for a singular message: %r" % source_of(message))
        tr.text = value


def save(tree, path):
    ET.indent(tree, space="    ")
    body = ET.tostring(tree.getroot(), encoding="unicode")
    with open(path, "w", encoding="utf-8") as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        f.write(body)
        f.write("\n")


def accelerators(text):
    """The number of '&' accelerator marks: not '&&' (a literal ampersand) nor an entity."""
    text = ENTITY.sub("", text.replace("&&", ""))
    return len(re.findall(r"&(?=\S)", text))


def problems(source, forms, plural):
    """What differs between a source text and its translation forms, as messages."""
    found = []
    if not forms or any(not f.strip() for f in forms):
        return ["empty translation"]
    want = sorted(m.group(0) for m in PLACEHOLDER.finditer(source))
    for f in forms:
        got = sorted(m.group(0) for m in PLACEHOLDER.finditer(f))
        if plural and "%n" in want and "%n" not in got and len(forms) > 1 and f is forms[0]:
            # Portuguese's singular may spell the one out ("um ponto"): accepted for form 1.
            got = sorted(got + ["%n"])
        if got != want:
            found.append("placeholders %s, source has %s: %r" % (got, want, f))
        if accelerators(f) != accelerators(source):
            found.append("%d accelerator(s), source has %d: %r"
                         % (accelerators(f), accelerators(source), f))
        if sorted(TAG.findall(f)) != sorted(TAG.findall(source)):
            found.append("HTML tags %s, source has %s: %r"
                         % (sorted(TAG.findall(f)), sorted(TAG.findall(source)), f))
    return found
