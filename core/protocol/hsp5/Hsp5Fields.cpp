#include "Hsp5Fields.h"

#include "Hsp5Layout.h"

#include <type_traits>

namespace DriveDesk {

namespace {

// Which of a service's four telegrams this is. Duplex services send their request fields the
// way a write request does and answer the way a read response does, whatever their access bit.
enum class Part : quint8 { ReadRequest, ReadResponse, WriteRequest, WriteResponse };

Part partOf(const Telegram &t)
{
    const bool request = t.direction == Direction::Request;
    if (isHsp5Duplex(t.service))
        return request ? Part::WriteRequest : Part::ReadResponse;
    if (t.access == Access::Write)
        return request ? Part::WriteRequest : Part::WriteResponse;
    return request ? Part::ReadRequest : Part::ReadResponse;
}

// Puts fields on the wire. Same member names as Reader, so one walk() serves both.
class Writer
{
public:
    explicit Writer(QByteArray &out) : m_out(out) {}

    void u8(quint8 v) { m_out.append(char(v)); }
    void ch(char v) { m_out.append(v); }
    void u16(quint16 v)
    {
        u8(quint8(v >> 8));
        u8(quint8(v));
    }
    void u32(quint32 v)
    {
        u16(quint16(v >> 16));
        u16(quint16(v));
    }
    void i16(qint16 v) { u16(quint16(v)); }
    void i32(qint32 v) { u32(quint32(v)); }
    void segments(const std::array<quint8, 5> &digits)
    {
        for (quint8 d : digits)
            u8(d);
    }
    // A length byte, then the bytes. The caller rejects what does not fit the layout.
    void counted(const QByteArray &bytes)
    {
        m_counted = bytes.size();
        u8(quint8(bytes.size()));
        m_out.append(bytes);
    }
    qsizetype countedSize() const { return m_counted; }

private:
    QByteArray &m_out;
    qsizetype m_counted = -1;
};

// Takes fields off the wire; reading past the end marks the body as not fitting.
class Reader
{
public:
    explicit Reader(QByteArrayView in) : m_in(in) {}

    void u8(quint8 &v) { v = take(); }
    void ch(char &v) { v = char(take()); }
    void u16(quint16 &v)
    {
        const quint16 high = take();
        v = quint16(high << 8 | take());
    }
    void u32(quint32 &v)
    {
        quint16 high = 0;
        quint16 low = 0;
        u16(high);
        u16(low);
        v = quint32(high) << 16 | low;
    }
    // Two's complement: the drive sends values sign extended.
    void i16(qint16 &v)
    {
        quint16 raw = 0;
        u16(raw);
        v = qint16(raw);
    }
    void i32(qint32 &v)
    {
        quint32 raw = 0;
        u32(raw);
        v = qint32(raw);
    }
    void segments(std::array<quint8, 5> &digits)
    {
        for (quint8 &d : digits)
            d = take();
    }
    void counted(QByteArray &bytes)
    {
        const qsizetype count = take();
        if (m_pos + count > m_in.size()) {
            m_ok = false;
            return;
        }
        bytes = m_in.sliced(m_pos, count).toByteArray();
        m_pos += count;
    }
    bool atEnd() const { return m_ok && m_pos == m_in.size(); }

private:
    quint8 take()
    {
        if (m_pos >= m_in.size()) {
            m_ok = false;
            return 0;
        }
        return quint8(m_in[m_pos++]);
    }

    QByteArrayView m_in;
    qsizetype m_pos = 0;
    bool m_ok = true;
};

template<typename T, typename D>
constexpr bool is = std::is_same_v<std::remove_const_t<D>, T>;

// The field order of every service, seed 000 sections 2.1-2.39 and docs/protocol-hsp5.md for
// the extensions. D is const when writing.
template<typename Io, typename D>
void walk(Io &io, D &d, Part part)
{
    [[maybe_unused]] const bool readReq = part == Part::ReadRequest;
    [[maybe_unused]] const bool readRsp = part == Part::ReadResponse;
    [[maybe_unused]] const bool writeReq = part == Part::WriteRequest;

    if constexpr (is<ParameterValue, D>) { // 0, 1, 14 (set = subindex)
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq)
            io.i32(d.value);
        if (readReq || writeReq)
            io.u8(d.set);
    } else if constexpr (is<ParameterLimits, D>) { // 2
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq) {
            io.i32(d.lower);
            io.i32(d.upper);
        }
    } else if constexpr (is<DefaultValue, D>) { // 3
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq)
            io.i32(d.value);
    } else if constexpr (is<PropertiesData, D>) { // 4
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq) {
            io.u32(d.properties1);
            io.u32(d.properties2);
        }
    } else if constexpr (is<DisplayScalingData, D>) { // 5
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq) {
            io.i16(d.divisor);
            io.i16(d.multiplier);
            io.i16(d.offset);
            io.u16(d.flags);
        }
    } else if constexpr (is<NameData, D>) { // 6, 11
        if (readReq || writeReq) {
            io.u16(d.address);
            io.u8(d.language);
        }
        if (readRsp || writeReq)
            io.counted(d.text);
    } else if constexpr (is<PlaintextIndicesData, D>) { // 7
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq) {
            io.u16(d.displayIndex);
            io.u16(d.displayCount);
            io.u16(d.combivisIndex);
            io.u16(d.combivisCount);
        }
    } else if constexpr (is<DisplayPlaintextData, D>) { // 8: the write puts the type first
        if (readReq || writeReq) {
            io.u16(d.index);
            io.u16(d.subindex);
            io.u8(d.language);
        }
        if (writeReq)
            io.u8(d.type);
        if (readRsp || writeReq)
            io.i32(d.value);
        if (readRsp)
            io.u8(d.type);
        if (readRsp || writeReq)
            io.segments(d.segments);
    } else if constexpr (is<CombivisPlaintextData, D>) { // 9: the write puts the type first
        if (readReq || writeReq) {
            io.u16(d.index);
            io.u8(d.definition);
            io.u8(d.subindex);
            io.u8(d.language);
        }
        if (writeReq)
            io.u8(d.type);
        if (readRsp || writeReq)
            io.i32(d.value);
        if (readRsp)
            io.u8(d.type);
        if (readRsp || writeReq)
            io.counted(d.text);
    } else if constexpr (is<GroupPropertiesData, D>) { // 10
        if (readReq || writeReq)
            io.u16(d.address);
        if (readRsp || writeReq) {
            io.u8(d.index);
            io.ch(d.id[0]);
            io.ch(d.id[1]);
            io.ch(d.shortcut);
            io.u16(d.properties);
            io.u8(d.highestNumber);
            io.u8(d.countMinusOne);
        }
    } else if constexpr (is<PlaintextDefinitionData, D>) { // 12
        if (readReq || writeReq) {
            io.u16(d.index);
            io.u8(d.definition);
            io.u8(d.language);
        }
        if (readRsp || writeReq) {
            io.u32(d.mask);
            io.u8(d.count);
            io.counted(d.text);
        }
    } else if constexpr (is<FieldbusData, D>) { // 13 (extension)
        if (readReq || writeReq) {
            io.u8(d.function);
            io.u16(d.index);
            io.u8(d.subindex);
        }
        if (readRsp || writeReq)
            io.counted(d.data);
    } else if constexpr (is<ProcessData32, D>) { // 16, 19, 48, 51
        if (readRsp || writeReq) {
            io.i32(d.values[0]);
            io.i32(d.values[1]);
        }
    } else if constexpr (is<ProcessData16, D>) { // 17, 20, 49, 52
        if (readRsp || writeReq) {
            for (auto &value : d.values)
                io.i16(value);
        }
    } else if constexpr (is<ScopeData, D>) { // 18
        if (readRsp || writeReq) {
            io.u16(d.timestamp);
            io.i32(d.wide[0]);
            io.i32(d.wide[1]);
            io.i16(d.narrow[0]);
            io.i16(d.narrow[1]);
        }
    } else if constexpr (is<ScopeRecordData, D>) { // 21 (extension), read only
        if (readReq) {
            io.u8(d.mode);
            io.u16(d.index);
        }
        if (readRsp) {
            io.u16(d.timestamp);
            for (auto &value : d.values)
                io.i32(value);
        }
    } else if constexpr (is<ProcessParameterData, D>) { // 50, 53
        if (readRsp || writeReq) {
            io.i32(d.value1);
            io.i16(d.value2);
            io.i16(d.value3);
        }
        if (writeReq)
            io.u16(d.parameterAddress);
        if (readRsp || writeReq)
            io.i32(d.parameterValue);
    } else if constexpr (is<DefaultCheckData, D>) { // 32, 33: both accesses send the same
        if (readReq || writeReq) {
            io.u16(d.address);
            io.u8(d.set);
        }
    }
}

} // namespace

qsizetype appendHsp5Fields(QByteArray &out, const Telegram &telegram)
{
    Writer writer(out);
    const Part part = partOf(telegram);
    std::visit([&](const auto &d) { walk(writer, d, part); }, telegram.data);
    if (telegram.isResponse())
        writer.u8(quint8(telegram.ack));
    return writer.countedSize();
}

bool readHsp5Fields(QByteArrayView body, Telegram &telegram)
{
    Reader reader(body);
    const Part part = partOf(telegram);
    std::visit([&](auto &d) { walk(reader, d, part); }, telegram.data);
    if (telegram.isResponse()) {
        quint8 ack = 0;
        reader.u8(ack);
        telegram.ack = Ack(ack);
    }
    return reader.atEnd();
}

} // namespace DriveDesk
