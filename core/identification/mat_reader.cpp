// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/mat_reader.h"

#include "core/io/file_io.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <matio.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <memory>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

namespace xyt {

namespace {

/// libmatio reports through a global log function (stderr by default); the messages of the
/// current thread's last failure are kept to name the reason in our own exception instead.
thread_local std::string matioMessage;

void keepMatioMessage(int /*level*/, char* message) {
    if (message && matioMessage.size() < 400)
        matioMessage = message;
}

void installMatioLog() {
    static std::once_flag once;
    std::call_once(once, [] { Mat_LogInitFunc("xytune", keepMatioMessage); });
}

struct MatCloser {
    void operator()(mat_t* m) const { Mat_Close(m); }
};
struct VarFreer {
    void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using MatHandle = std::unique_ptr<mat_t, MatCloser>;
using VarHandle = std::unique_ptr<matvar_t, VarFreer>;

std::uint32_t read32(const unsigned char* p, bool swap) {
    std::uint32_t v = 0;
    std::memcpy(&v, p, 4);
    return swap ? __builtin_bswap32(v) : v;
}

/// A v5 data element tag at b (8 bytes; the small format packs the size in the upper half).
struct V5Tag {
    std::uint32_t type = 0, size = 0, headerBytes = 8;
};
V5Tag v5Tag(const unsigned char* b, bool swap) {
    const std::uint32_t first = read32(b, swap);
    if (first >> 16)
        return {first & 0xFFFFu, first >> 16, 4};
    return {first, read32(b + 4, swap), 8};
}

/**
 * The array header at the start of a miMATRIX body (@p avail bytes read of @p bodySize): flags,
 * dimensions (miINT32, at least two), name (miINT8). libmatio allocates by the dimensions and the
 * name length, so both are bounded by what the element can hold: at least one byte per element.
 */
bool v5ArrayHeaderFits(const unsigned char* b, std::size_t avail, std::uint64_t bodySize,
                       bool swap) {
    if (bodySize == 0)
        return true; // an empty matrix element: libmatio skips it
    if (avail < 16 + 8)
        return false;
    const V5Tag flags = v5Tag(b, swap);
    if (flags.type != 6 || flags.size != 8 || flags.headerBytes != 8)
        return false;
    std::size_t at = 16;
    const V5Tag dims = v5Tag(b + at, swap);
    if (dims.type != 5 || dims.size < 8 || dims.size % 4 != 0 || dims.size > 4 * 64)
        return false;
    at += dims.headerBytes;
    if (avail < at + dims.size)
        return false;
    std::uint64_t elements = 1;
    for (std::uint32_t k = 0; k < dims.size / 4; ++k) {
        const std::uint32_t d = read32(b + at + 4 * k, swap);
        if (d > 0x7FFFFFFFu)
            return false;
        elements *= d;
        if (elements > bodySize)
            return false;
    }
    at += (dims.size + 7) / 8 * 8;
    if (avail < at + 4)
        return false;
    const V5Tag name = v5Tag(b + at, swap);
    return name.type == 1 && name.size <= 4096 && at + name.headerBytes + name.size <= bodySize;
}

/// The top-level elements of a v5 file: each miMATRIX (14) or miCOMPRESSED (15), within the file,
/// its array header sane (a compressed one inflated far enough to see it).
bool v5ElementsFit(const std::string& path, std::uint64_t fileSize, bool swap) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
        return false;
    std::uint64_t offset = 128;
    bool ok = true;
    std::vector<unsigned char> buffer(4096);
    while (ok && offset < fileSize) {
        unsigned char tag[8];
        if (fileSize - offset < 8 || ::pread(fd, tag, 8, static_cast<off_t>(offset)) != 8) {
            ok = false;
            break;
        }
        const std::uint32_t type = read32(tag, swap), size = read32(tag + 4, swap);
        if ((type != 14 && type != 15) || size > fileSize - offset - 8) {
            ok = false;
            break;
        }
        const std::size_t avail = std::min<std::size_t>(size, buffer.size());
        if (::pread(fd, buffer.data(), avail, static_cast<off_t>(offset + 8)) !=
            static_cast<ssize_t>(avail)) {
            ok = false;
            break;
        }
        if (type == 14) {
            ok = v5ArrayHeaderFits(buffer.data(), avail, size, swap);
        } else {
            // Inflate the head: the stream holds one miMATRIX element (tag, then its body).
            unsigned char head[1024];
            z_stream z{};
            ok = inflateInit(&z) == Z_OK;
            if (ok) {
                z.next_in = buffer.data();
                z.avail_in = static_cast<uInt>(avail);
                z.next_out = head;
                z.avail_out = sizeof head;
                const int r = inflate(&z, Z_SYNC_FLUSH);
                const std::size_t got = sizeof head - z.avail_out;
                inflateEnd(&z);
                ok = (r == Z_OK || r == Z_STREAM_END || r == Z_BUF_ERROR) && got >= 8;
                if (ok) {
                    const std::uint32_t innerType = read32(head, swap),
                                        innerSize = read32(head + 4, swap);
                    // Deflate expands at most 1032:1.
                    ok = innerType == 14 && std::uint64_t(innerSize) <= 1032ull * size + 64 &&
                         v5ArrayHeaderFits(head + 8, got - 8, innerSize, swap);
                }
            }
        }
        offset += 8 + std::uint64_t(size);
    }
    ::close(fd);
    return ok;
}

/// The v4 matrices of the file, walked header by header (see checkHeader).
bool v4ChainFits(const std::string& path, std::uint64_t fileSize, bool swap) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
        return false;
    std::uint64_t offset = 0;
    bool ok = false;
    for (int matrices = 0; matrices < 100000; ++matrices) {
        if (offset == fileSize) {
            ok = matrices > 0;
            break;
        }
        unsigned char h[20];
        if (fileSize - offset < 20 || ::pread(fd, h, 20, static_cast<off_t>(offset)) != 20)
            break;
        const std::uint32_t type = read32(h, swap), rows = read32(h + 4, swap),
                            cols = read32(h + 8, swap), imag = read32(h + 12, swap),
                            nameLength = read32(h + 16, swap);
        const unsigned m = type / 1000, o = type / 100 % 10, p = type / 10 % 10, t = type % 10;
        if (type >= 5000 || m > 4 || o != 0 || p > 5 || t > 2 || imag > 1 || nameLength < 2 ||
            nameLength > 64)
            break;
        const std::uint64_t bytesPer[] = {8, 4, 4, 2, 2, 1};
        if (rows > (1u << 30) || cols > (1u << 30))
            break;
        const std::uint64_t elements = std::uint64_t(rows) * std::uint64_t(cols);
        const std::uint64_t need =
            20 + std::uint64_t(nameLength) + elements * bytesPer[p] * (imag ? 2 : 1);
        if (elements > fileSize || need > fileSize - offset)
            break;
        offset += need;
    }
    ::close(fd);
    return ok;
}

/**
 * Our own look at the first bytes, so that only something shaped like a MAT file reaches
 * libmatio: a v5/v7.3 header (text, subsystem offset, version 0x0100 or 0x0200, "IM"/"MI"), or a
 * v4 matrix header whose type code, sizes and name length are valid and whose data fits in the
 * file. Returns "" when acceptable, else why not.
 */
Diagnostic checkHeader(const std::string& path, std::uint64_t fileSize) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
        throw FileError(path, systemErrorDiagnostic(errno));
    unsigned char h[128] = {};
    const ssize_t got = ::read(fd, h, sizeof h);
    ::close(fd);
    if (got < 0)
        throw FileError(path, systemErrorDiagnostic(errno));
    if (got == 128 && ((h[126] == 'I' && h[127] == 'M') || (h[126] == 'M' && h[127] == 'I'))) {
        const bool little = h[126] == 'I'; // "IM" read as bytes: written little-endian
        const unsigned version = little ? (h[124] | (h[125] << 8)) : ((h[124] << 8) | h[125]);
        if (version != 0x0100 && version != 0x0200)
            return makeDiagnostic("ident_mat_header_version", {std::to_string(version)});
        if (version == 0x0100 && fileSize < 128 + 8)
            return makeDiagnostic("ident_mat_header_no_variable");
        if (version == 0x0100 &&
            !v5ElementsFit(path, fileSize, little != (std::endian::native == std::endian::little)))
            return makeDiagnostic("ident_mat_element_not_fit");
        return {};
    }
    if (got >= 20) {
        // v4: a chain of matrices, each five int32 (type MOPT, rows, columns, imaginary flag, name
        // length), the name and the data, in either byte order. libmatio allocates what a header
        // claims, so every header of the file is checked and the chain must end exactly at the
        // end of the file: no allocation can then exceed the file's size.
        for (const bool swap : {false, true})
            if (v4ChainFits(path, fileSize, swap))
                return {};
    }
    return makeDiagnostic("ident_mat_no_header");
}

/// Opens the file after the size and header checks. @throws FileError / InvalidInput.
MatHandle openMat(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw FileError(path, errno == ENOENT ? makeDiagnostic("io_no_such_file")
                                              : systemErrorDiagnostic(errno));
    if (!S_ISREG(st.st_mode))
        throw FileError(path, makeDiagnostic("io_not_regular_file"));
    if (static_cast<std::uint64_t>(st.st_size) > kMaxExperimentBytes)
        throw FileError(
            path, makeDiagnostic("io_larger_than_limit", {std::to_string(kMaxExperimentBytes)}));
    if (const Diagnostic why = checkHeader(path, static_cast<std::uint64_t>(st.st_size));
        !why.text.empty())
        throw InvalidInput(path, makeDiagnostic("ident_mat_not_mat", {why}));
    installMatioLog();
    matioMessage.clear();
    mat_t* m = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
    if (!m)
        throw InvalidInput(path, matioMessage.empty()
                                     ? makeDiagnostic("ident_mat_cannot_open")
                                     : makeDiagnostic("ident_mat_cannot_open_why",
                                                      {shownCell(matioMessage, 200)}));
    return MatHandle(m);
}

const char* className(int c) {
    switch (c) {
    case MAT_C_CELL:
        return "cell";
    case MAT_C_STRUCT:
        return "struct";
    case MAT_C_OBJECT:
        return "object";
    case MAT_C_CHAR:
        return "char";
    case MAT_C_SPARSE:
        return "sparse";
    case MAT_C_DOUBLE:
        return "double";
    case MAT_C_SINGLE:
        return "single";
    case MAT_C_INT8:
        return "int8";
    case MAT_C_UINT8:
        return "uint8";
    case MAT_C_INT16:
        return "int16";
    case MAT_C_UINT16:
        return "uint16";
    case MAT_C_INT32:
        return "int32";
    case MAT_C_UINT32:
        return "uint32";
    case MAT_C_INT64:
        return "int64";
    case MAT_C_UINT64:
        return "uint64";
    case MAT_C_FUNCTION:
        return "function";
    case MAT_C_OPAQUE:
        return "opaque";
    default:
        return "unknown";
    }
}

bool numericClass(int c) {
    return c == MAT_C_DOUBLE || c == MAT_C_SINGLE || c == MAT_C_INT8 || c == MAT_C_UINT8 ||
           c == MAT_C_INT16 || c == MAT_C_UINT16 || c == MAT_C_INT32 || c == MAT_C_UINT32 ||
           c == MAT_C_INT64 || c == MAT_C_UINT64;
}

/// "2 x 3 x 4": the dimensions as written in a message.
std::string dimensionText(const matvar_t& v) {
    std::string text;
    for (int k = 0; k < v.rank && v.dims; ++k)
        text += (k ? " x " : "") + std::to_string(v.dims[k]);
    return text;
}

/// What a variable that is not a real numeric vector is, in words ("a cell array", ...).
Diagnostic notNumericWhy(int classType) {
    switch (classType) {
    case MAT_C_CELL:
        return makeDiagnostic("ident_mat_cell");
    case MAT_C_STRUCT:
        return makeDiagnostic("ident_mat_struct");
    case MAT_C_OBJECT:
        return makeDiagnostic("ident_mat_object");
    case MAT_C_CHAR:
        return makeDiagnostic("ident_mat_char");
    case MAT_C_SPARSE:
        return makeDiagnostic("ident_mat_sparse");
    case MAT_C_FUNCTION:
        return makeDiagnostic("ident_mat_function");
    case MAT_C_OPAQUE:
        return makeDiagnostic("ident_mat_opaque");
    default:
        return makeDiagnostic("ident_mat_unknown_class");
    }
}

MatVariableInfo describe(const matvar_t& v) {
    MatVariableInfo info;
    info.name = v.name ? v.name : "";
    info.className = className(v.class_type);
    if (v.rank == 2 && v.dims) {
        info.rows = v.dims[0];
        info.columns = v.dims[1];
    }
    // What the variable claims, saturated: a header may state any dimensions.
    info.elements = v.rank >= 1 && v.dims ? 1 : 0;
    for (int k = 0; k < v.rank && v.dims; ++k)
        info.elements = v.dims[k] != 0 && info.elements > UINT64_MAX / v.dims[k]
                            ? UINT64_MAX
                            : info.elements * v.dims[k];
    if (!numericClass(v.class_type))
        info.whyNot =
            v.class_type == MAT_C_EMPTY ? makeDiagnostic("is_empty") : notNumericWhy(v.class_type);
    else if (v.isLogical)
        info.whyNot = makeDiagnostic("ident_mat_logical");
    else if (v.isComplex)
        info.whyNot = makeDiagnostic("ident_mat_complex");
    else if (v.rank > 2 && v.dims)
        info.whyNot =
            makeDiagnostic("ident_mat_nd_array", {dimensionText(v), std::to_string(v.rank)});
    else if (v.rank != 2 || !v.dims)
        info.whyNot = makeDiagnostic("ident_mat_dimensions", {std::to_string(v.rank)});
    else if (info.rows == 0 || info.columns == 0)
        info.whyNot = makeDiagnostic("is_empty");
    else if (info.rows != 1 && info.columns != 1)
        info.whyNot = makeDiagnostic("ident_mat_matrix",
                                     {std::to_string(info.rows), std::to_string(info.columns)});
    else if (info.name.empty())
        info.whyNot = makeDiagnostic("ident_mat_no_name");
    info.usable = info.whyNot.text.empty();
    return info;
}

template <class T> void convert(const void* data, std::size_t n, std::vector<double>& out) {
    out.resize(n);
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) {
        T v;
        std::memcpy(&v, bytes + k * sizeof(T), sizeof(T));
        out[k] = static_cast<double>(v);
    }
}

/// A variable whose data libmatio could not read, with libmatio's reason when it gave one.
InvalidInput unreadable(const std::string& path, const std::string& name) {
    return InvalidInput(path,
                        matioMessage.empty()
                            ? makeDiagnostic("ident_mat_unreadable", {shownCell(name)})
                            : makeDiagnostic("ident_mat_unreadable_why",
                                             {shownCell(name), shownCell(matioMessage, 200)}));
}

/// The elements of a read variable as doubles. @throws InvalidInput when the data is absent or
/// short.
std::vector<double> elements(const matvar_t& v, const std::string& path, const std::string& name) {
    const std::size_t n = v.dims[0] * v.dims[1];
    const std::size_t size = Mat_SizeOfClass(v.class_type);
    if (!v.data || size == 0 || n > std::numeric_limits<std::size_t>::max() / size ||
        v.nbytes < n * size)
        throw unreadable(path, name);
    std::vector<double> out;
    switch (v.class_type) {
    case MAT_C_DOUBLE:
        convert<double>(v.data, n, out);
        break;
    case MAT_C_SINGLE:
        convert<float>(v.data, n, out);
        break;
    case MAT_C_INT8:
        convert<std::int8_t>(v.data, n, out);
        break;
    case MAT_C_UINT8:
        convert<std::uint8_t>(v.data, n, out);
        break;
    case MAT_C_INT16:
        convert<std::int16_t>(v.data, n, out);
        break;
    case MAT_C_UINT16:
        convert<std::uint16_t>(v.data, n, out);
        break;
    case MAT_C_INT32:
        convert<std::int32_t>(v.data, n, out);
        break;
    case MAT_C_UINT32:
        convert<std::uint32_t>(v.data, n, out);
        break;
    case MAT_C_INT64:
        convert<std::int64_t>(v.data, n, out);
        break;
    case MAT_C_UINT64:
        convert<std::uint64_t>(v.data, n, out);
        break;
    default:
        throw InvalidInput(path, makeDiagnostic("ident_mat_not_numeric", {shownCell(name)}));
    }
    return out;
}

/// The most variables listed: far beyond any experiment, and it bounds the work on a file of
/// millions of empty elements.
constexpr std::size_t kMaxListedVariables = 100000;

std::vector<MatVariableInfo> listOpen(mat_t* m) {
    std::vector<MatVariableInfo> vars;
    Mat_Rewind(m);
    while (vars.size() < kMaxListedVariables) {
        const VarHandle v(Mat_VarReadNextInfo(m));
        if (!v)
            break;
        vars.push_back(describe(*v));
    }
    return vars;
}

} // namespace

MatFileInfo listMatVariables(const std::string& path) {
    const MatHandle m = openMat(path);
    MatFileInfo info;
    switch (Mat_GetVersion(m.get())) {
    case MAT_FT_MAT4:
        info.version = "v4";
        break;
    case MAT_FT_MAT5:
        info.version = "v5";
        break;
    case MAT_FT_MAT73:
        info.version = "v7.3";
        break;
    default:
        info.version = "unknown";
        break;
    }
    info.variables = listOpen(m.get());
    return info;
}

namespace {

/// "the real numeric vectors are: t, u, y" (cut near 2000 characters), for a name not usable.
Diagnostic usableList(const std::vector<MatVariableInfo>& vars) {
    std::string list;
    for (const MatVariableInfo& v : vars)
        if (v.usable && list.size() < 2000)
            list += (list.empty() ? "" : ", ") + shownCell(v.name);
    return list.empty() ? makeDiagnostic("ident_mat_usable_none")
                        : makeDiagnostic("ident_mat_usable", {list});
}

Diagnostic elementsText(const MatVariableInfo& v) {
    return v.rows * v.columns == v.elements
               ? makeDiagnostic("ident_mat_elements_matrix",
                                {std::to_string(v.rows), std::to_string(v.columns)})
               : makeDiagnostic("ident_mat_elements", {std::to_string(v.elements)});
}

/// The listed variables @p names refers to, every check made before any data is read.
std::vector<const MatVariableInfo*> chosenVariables(const std::string& path,
                                                    const std::vector<MatVariableInfo>& vars,
                                                    const std::vector<std::string>& names) {
    if (names.size() > kMaxExperimentColumns)
        throw InvalidInput(path, makeDiagnostic("ident_mat_too_many_asked",
                                                {std::to_string(names.size()),
                                                 std::to_string(kMaxExperimentColumns)}));
    std::vector<const MatVariableInfo*> chosen;
    std::uint64_t total = 0;
    for (const std::string& name : names) {
        const auto found = std::find_if(vars.begin(), vars.end(),
                                        [&](const MatVariableInfo& v) { return v.name == name; });
        if (found == vars.end())
            throw InvalidInput(
                path, makeDiagnostic("ident_mat_no_variable", {shownCell(name), usableList(vars)}));
        const MatVariableInfo& v = *found;
        if (!v.usable)
            throw InvalidInput(path, makeDiagnostic("ident_mat_not_vector",
                                                    {shownCell(name), v.whyNot, usableList(vars)}));
        if (std::find(chosen.begin(), chosen.end(), &v) != chosen.end())
            throw InvalidInput(path, makeDiagnostic("ident_mat_asked_twice", {shownCell(name)}));
        if (v.elements > kMaxMatVariableElements)
            throw InvalidInput(path, makeDiagnostic("ident_mat_variable_claims",
                                                    {shownCell(name), elementsText(v),
                                                     std::to_string(kMaxMatVariableElements)}));
        total += v.elements;
        if (total > kMaxMatTableElements)
            throw InvalidInput(path, makeDiagnostic("ident_mat_total_claims",
                                                    {shownCell(name), std::to_string(total),
                                                     std::to_string(kMaxMatTableElements)}));
        chosen.push_back(&v);
    }
    return chosen;
}

/// Every usable variable within the bounds (see readMat), the others named in @p warnings.
std::vector<const MatVariableInfo*> everyUsableVariable(const std::vector<MatVariableInfo>& vars,
                                                        std::vector<Diagnostic>& warnings) {
    std::vector<const MatVariableInfo*> chosen;
    std::uint64_t total = 0;
    std::size_t leftOut = 0;
    const auto leave = [&](const MatVariableInfo& v, const Diagnostic& why) {
        if (++leftOut <= 10)
            warnings.push_back(
                makeDiagnostic("ident_mat_not_read", {shownCell(v.name), elementsText(v), why}));
    };
    for (const MatVariableInfo& v : vars) {
        if (!v.usable)
            continue;
        // A v4 file may repeat a name (each matrix is written on its own); the table's columns
        // are named, so only the first of a name is read (fuzz_mat_reader, corpus
        // crash-repeated-name).
        if (std::any_of(chosen.begin(), chosen.end(),
                        [&v](const MatVariableInfo* c) { return c->name == v.name; }))
            continue;
        if (v.elements > kMaxMatVariableElements)
            leave(v, makeDiagnostic("ident_mat_why_variable_limit",
                                    {std::to_string(kMaxMatVariableElements)}));
        else if (chosen.size() == kMaxExperimentColumns)
            leave(v, makeDiagnostic("ident_mat_why_column_limit",
                                    {std::to_string(kMaxExperimentColumns)}));
        else if (total + v.elements > kMaxMatTableElements)
            leave(v, makeDiagnostic("ident_mat_why_total_limit",
                                    {std::to_string(total), std::to_string(kMaxMatTableElements)}));
        else {
            total += v.elements;
            chosen.push_back(&v);
        }
    }
    if (leftOut > 10)
        warnings.push_back(
            makeDiagnostic("ident_mat_more_not_read", {std::to_string(leftOut - 10)}));
    return chosen;
}

} // namespace

ExperimentTable readMat(const std::string& path, const std::vector<std::string>& names) {
    const MatHandle m = openMat(path);
    const std::vector<MatVariableInfo> vars = listOpen(m.get());

    ExperimentTable t;
    t.fileName = path;
    t.rowLabel = "element";
    const std::vector<const MatVariableInfo*> chosen =
        names.empty() ? everyUsableVariable(vars, t.warnings) : chosenVariables(path, vars, names);
    // A second walk over the headers, in the order listed, reads the data of the chosen ones
    // only (Mat_VarRead by name would walk the headers again for every variable).
    std::vector<std::vector<double>> data(chosen.size());
    std::vector<std::size_t> slotOf(vars.size(), chosen.size()); // chosen.size(): not chosen
    for (std::size_t k = 0; k < chosen.size(); ++k)
        slotOf[std::size_t(chosen[k] - vars.data())] = k;
    Mat_Rewind(m.get());
    for (std::size_t index = 0, done = 0; index < vars.size() && done < chosen.size(); ++index) {
        matioMessage.clear();
        const VarHandle v(Mat_VarReadNextInfo(m.get()));
        if (!v)
            break;
        const std::size_t slot = slotOf[index];
        if (slot == chosen.size())
            continue;
        const MatVariableInfo& info = *chosen[slot];
        if (Mat_VarReadDataAll(m.get(), v.get()) != 0 || !v->name || v->name != info.name ||
            v->rank != 2 || !v->dims || !numericClass(v->class_type) || v->isComplex ||
            v->dims[0] * v->dims[1] != info.rows * info.columns)
            throw unreadable(path, info.name);
        data[slot] = elements(*v, path, info.name);
        ++done;
    }
    std::size_t longest = 0;
    for (std::size_t k = 0; k < chosen.size(); ++k) {
        const std::string& name = chosen[k]->name;
        if (data[k].empty()) // the second walk ended early: the file changed or libmatio failed
            throw unreadable(path, name);
        t.addColumn(name, 0);
        const std::size_t c = t.names.size() - 1;
        t.columns[c] = std::move(data[k]);
        for (std::size_t r = 0; r < t.columns[c].size(); ++r)
            if (!std::isfinite(t.columns[c][r])) {
                noteCellProblem(t, c, r, std::isnan(t.columns[c][r]) ? "NaN" : "Inf",
                                makeDiagnostic("not_finite_value"));
                break;
            }
        longest = std::max(longest, t.columns[c].size());
    }
    t.rowNumbers.resize(longest);
    for (std::size_t k = 0; k < longest; ++k)
        t.rowNumbers[k] = k + 1;
    return t;
}

} // namespace xyt
