/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vtkSeries.H"
#include "vtkAtomicFile.H"
#include "OSspecific.H"
#include "error.H"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Where and why a series file is not the JSON we expect
struct jsonError
{
    std::string what;
    std::string::size_type pos;
};


//- Just enough of a JSON reader for a series file: the steps are read, any
//  other member or value is checked for syntax and skipped
class jsonReader
{
    const std::string& text_;
    std::string::size_type pos_ = 0;

    //- Nesting allowed in skipped values; a deeper file is not a series
    static constexpr int maxDepth = 64;

    [[noreturn]] void error(const std::string& what) const
    {
        throw jsonError{what, pos_};
    }

    void skipSpace()
    {
        while
        (
            pos_ < text_.size()
         && (text_[pos_] == ' ' || text_[pos_] == '\t'
          || text_[pos_] == '\n' || text_[pos_] == '\r')
        )
        {
            ++pos_;
        }
    }

    void skipLiteral(const char* literal)
    {
        const std::string word(literal);
        if (text_.compare(pos_, word.size(), word) != 0)
        {
            error("unexpected character '" + text_.substr(pos_, 1) + "'");
        }
        pos_ += word.size();
    }

    static void appendUtf8(std::string& s, const unsigned code)
    {
        if (code < 0x80)
        {
            s += char(code);
        }
        else if (code < 0x800)
        {
            s += char(0xC0 | (code >> 6));
            s += char(0x80 | (code & 0x3F));
        }
        else
        {
            s += char(0xE0 | (code >> 12));
            s += char(0x80 | ((code >> 6) & 0x3F));
            s += char(0x80 | (code & 0x3F));
        }
    }


public:

    explicit jsonReader(const std::string& text)
    :
        text_(text)
    {}

    //- True (and consumed) if the next non-blank character is c
    bool accept(const char c)
    {
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == c)
        {
            ++pos_;
            return true;
        }
        return false;
    }

    void expect(const char c)
    {
        if (!accept(c))
        {
            error(std::string("expected '") + c + "'");
        }
    }

    bool atEnd()
    {
        skipSpace();
        return pos_ == text_.size();
    }

    std::string readString()
    {
        expect('"');

        std::string s;
        while (true)
        {
            if (pos_ >= text_.size())
            {
                error("unterminated string");
            }

            const char c = text_[pos_++];
            if (c == '"')
            {
                return s;
            }
            else if (static_cast<unsigned char>(c) < 0x20)
            {
                error("control character in a string");
            }
            else if (c != '\\')
            {
                s += c;
                continue;
            }

            if (pos_ >= text_.size())
            {
                error("unterminated string");
            }

            switch (const char e = text_[pos_++])
            {
                case '"': case '\\': case '/': s += e; break;
                case 'b': s += '\b'; break;
                case 'f': s += '\f'; break;
                case 'n': s += '\n'; break;
                case 'r': s += '\r'; break;
                case 't': s += '\t'; break;
                case 'u':
                {
                    unsigned code = 0;
                    const auto hex = text_.substr(pos_, 4);
                    const auto end = hex.data() + hex.size();
                    const auto res = std::from_chars(hex.data(), end, code, 16);
                    if (hex.size() != 4 || res.ptr != end)
                    {
                        error("bad \\u escape");
                    }
                    pos_ += 4;
                    appendUtf8(s, code);
                    break;
                }
                default:
                    error(std::string("bad escape \\") + e);
            }
        }
    }

    double readNumber()
    {
        skipSpace();

        const auto start = pos_;
        while
        (
            pos_ < text_.size()
         && std::string("+-0123456789.eE").find(text_[pos_]) != std::string::npos
        )
        {
            ++pos_;
        }

        // from_chars: exact, and independent of the C locale
        double value = 0;
        const char* first = text_.data() + start;
        const char* last = text_.data() + pos_;
        const auto res = std::from_chars(first, last, value);

        if (start == pos_ || res.ec != std::errc() || res.ptr != last)
        {
            pos_ = start;
            error("expected a number");
        }
        return value;
    }

    //- Check and skip any value
    void skipValue(const int depth = 0)
    {
        if (depth > maxDepth)
        {
            error("values nested too deeply");
        }

        skipSpace();
        const char c = pos_ < text_.size() ? text_[pos_] : '\0';

        if (c == '"')
        {
            readString();
        }
        else if (c == '{')
        {
            expect('{');
            if (accept('}'))
            {
                return;
            }
            do
            {
                readString();
                expect(':');
                skipValue(depth + 1);
            } while (accept(','));
            expect('}');
        }
        else if (c == '[')
        {
            expect('[');
            if (accept(']'))
            {
                return;
            }
            do
            {
                skipValue(depth + 1);
            } while (accept(','));
            expect(']');
        }
        else if (c == 't')
        {
            skipLiteral("true");
        }
        else if (c == 'f')
        {
            skipLiteral("false");
        }
        else if (c == 'n')
        {
            skipLiteral("null");
        }
        else
        {
            readNumber();
        }
    }

    //- One { "name" : ..., "time" : ... } object
    Foam::SPH::vtkSeries::step readStep()
    {
        Foam::SPH::vtkSeries::step s;
        bool hasName = false;
        bool hasTime = false;

        expect('{');
        if (!accept('}'))
        {
            do
            {
                const std::string key = readString();
                expect(':');
                if (key == "name")
                {
                    s.name = readString();
                    hasName = !s.name.empty();
                }
                else if (key == "time")
                {
                    s.time = readNumber();
                    hasTime = true;
                }
                else
                {
                    skipValue();
                }
            } while (accept(','));
            expect('}');
        }

        if (!hasName || !hasTime)
        {
            error("a file entry needs a non-empty \"name\" and a \"time\"");
        }
        return s;
    }

    //- The whole series file
    Foam::DynamicList<Foam::SPH::vtkSeries::step> readSeries()
    {
        Foam::DynamicList<Foam::SPH::vtkSeries::step> steps;
        bool hasFiles = false;

        expect('{');
        if (!accept('}'))
        {
            do
            {
                const std::string key = readString();
                expect(':');
                if (key == "files")
                {
                    hasFiles = true;
                    expect('[');
                    if (!accept(']'))
                    {
                        do
                        {
                            steps.append(readStep());
                        } while (accept(','));
                        expect(']');
                    }
                }
                else
                {
                    skipValue();
                }
            } while (accept(','));
            expect('}');
        }

        if (!atEnd())
        {
            error("text after the closing '}'");
        }
        if (!hasFiles)
        {
            error("no \"files\" list");
        }
        return steps;
    }
};


//- JSON string literal of s
std::string jsonString(const std::string& s)
{
    std::string out("\"");
    for (const char c : s)
    {
        if (c == '"' || c == '\\')
        {
            out += '\\';
            out += c;
        }
        else if (static_cast<unsigned char>(c) < 0x20)
        {
            char buf[8];
            std::snprintf(buf, sizeof(buf), "\\u%04x", unsigned(c));
            out += buf;
        }
        else
        {
            out += c;
        }
    }
    return out + '"';
}


//- Shortest text that reads back to the same double: 0.1 gives "0.1", and
//  0.1 + 0.2 gives "0.30000000000000004" rather than a rounded 0.3 that
//  would no longer compare equal after the file is read again
std::string jsonNumber(const double value)
{
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof(buf), value);
    return std::string(buf, res.ptr);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::vtkSeries::read()
{
    if (!isFile(file_, false))
    {
        return;
    }

    std::ifstream is(file_);
    std::ostringstream contents;
    contents << is.rdbuf();

    if (!is)
    {
        WarningInFunction
            << "Cannot read the VTK series file " << file_ << nl
            << "    Starting a new series: the file is rewritten at the next append"
            << endl;
        return;
    }

    const std::string text(contents.str());

    try
    {
        steps_ = jsonReader(text).readSeries();
    }
    catch (const jsonError& err)
    {
        // Count lines so the message points at the place in an editor
        const auto upTo = text.substr(0, err.pos);
        const label line = 1 + std::count(upTo.begin(), upTo.end(), '\n');

        WarningInFunction
            << "Malformed VTK series file " << file_ << " at line " << line
            << ": " << err.what.c_str() << nl
            << "    Starting a new series: the file is rewritten at the next append"
            << endl;
        steps_.clear();
    }
}


Foam::fileName Foam::SPH::vtkSeries::relativeName(const fileName& file) const
{
    if (!file.hasPath())
    {
        return file;
    }

    fileName dir(file_.path());
    fileName absFile(file);
    dir.toAbsolute();
    absFile.toAbsolute();
    dir.clean();
    absFile.clean();

    const fileName rel(absFile.relative(dir));

    if (rel == absFile)
    {
        FatalErrorInFunction
            << "Cannot list " << file << " in the VTK series " << file_ << nl
            << "    because it is not inside the series folder " << file_.path()
            << exit(FatalError);
    }

    return rel;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkSeries::vtkSeries(const fileName& seriesFile)
:
    file_(seriesFile)
{
    read();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::vtkSeries::append(const fileName& file, const scalar time)
{
    if (!std::isfinite(time))
    {
        FatalErrorInFunction
            << "Cannot list " << file << " in the VTK series " << file_
            << " at time " << time << ": the time is not a finite number"
            << exit(FatalError);
    }

    const fileName name(relativeName(file));

    // A step at time >= the new time is from a run this one restarted
    // before; the same name at an earlier time is a file being rewritten
    label kept = 0;
    forAll(steps_, i)
    {
        if (steps_[i].name != name && steps_[i].time < time)
        {
            steps_[kept++] = steps_[i];
        }
    }
    steps_.resize(kept);

    steps_.append(step{name, time});

    write();
}


void Foam::SPH::vtkSeries::write() const
{
    vtkAtomicFile out(file_);

    {
        std::ofstream os(out.tmpName());

        os  << "{\n"
            << "  \"file-series-version\" : \"1.0\",\n"
            << "  \"files\" : [\n";

        forAll(steps_, i)
        {
            os  << "    { \"name\" : " << jsonString(steps_[i].name)
                << ", \"time\" : " << jsonNumber(steps_[i].time) << " }"
                << (i + 1 < steps_.size() ? ",\n" : "\n");
        }

        os  << "  ]\n"
            << "}\n";

        os.close();
        if (!os)
        {
            out.fail("writing the temporary file " + out.tmpName() + " failed");
        }
    }

    out.commit();
}


// ************************************************************************* //
