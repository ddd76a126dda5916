#include "Services.h"

#include "DriveState.h"

namespace DriveDesk::Sim {

namespace {

constexpr quint8 kIdentifyFunction = 1; // fktVfdIdentify (seed 002 2.15.2)

bool validLanguage(quint8 language)
{
    return language < kLanguages;
}

Telegram answerParameterMetadata(const DriveState &state, const Telegram &request)
{
    const ParameterDatabase &db = state.db();
    switch (request.service) {
    case Service::Limits: {
        const auto *d = request.as<ParameterLimits>();
        if (!d)
            return malformed(request);
        const SimParameter *p = db.find(d->address);
        if (!p)
            return answer(request, Ack::AddressInvalid, ParameterLimits { d->address, 0, 0 });
        return answer(request, Ack::Ok, ParameterLimits { d->address, p->minimum, p->maximum });
    }
    case Service::DefaultValue: {
        const auto *d = request.as<DefaultValue>();
        if (!d)
            return malformed(request);
        const SimParameter *p = db.find(d->address);
        if (!p)
            return answer(request, Ack::AddressInvalid, DefaultValue { d->address, 0 });
        return answer(request, Ack::Ok, DefaultValue { d->address, p->defaultValue });
    }
    case Service::Properties: {
        const auto *d = request.as<PropertiesData>();
        if (!d)
            return malformed(request);
        const SimParameter *p = db.find(d->address);
        if (!p)
            return answer(request, Ack::AddressInvalid, PropertiesData { d->address, 0, 0 });
        return answer(request, Ack::Ok,
                      PropertiesData { d->address, p->properties1, p->properties2 });
    }
    case Service::DisplayScaling: {
        const auto *d = request.as<DisplayScalingData>();
        if (!d)
            return malformed(request);
        const SimParameter *p = db.find(d->address);
        if (!p)
            return answer(request, Ack::AddressInvalid,
                          DisplayScalingData { d->address, 0, 0, 0, 0 });
        DisplayScalingData scaling = p->scaling;
        scaling.address = d->address;
        return answer(request, Ack::Ok, scaling);
    }
    case Service::ParameterName: {
        const auto *d = request.as<NameData>();
        if (!d)
            return malformed(request);
        const SimParameter *p = db.find(d->address);
        if (!p)
            return answer(request, Ack::AddressInvalid, NameData { d->address, d->language, {} });
        if (!validLanguage(d->language))
            return answer(request, Ack::LanguageInvalid, NameData { d->address, d->language, {} });
        return answer(request, Ack::Ok, NameData { d->address, d->language, p->name[d->language] });
    }
    case Service::PlaintextIndices: {
        const auto *d = request.as<PlaintextIndicesData>();
        if (!d)
            return malformed(request);
        const SimParameter *p = db.find(d->address);
        if (!p)
            return answer(request, Ack::AddressInvalid,
                          PlaintextIndicesData { d->address, 0, 0, 0, 0 });
        PlaintextIndicesData indices { d->address, 0, 0, 0, 0 };
        if (p->enumeration >= 0) {
            const Enumeration &e = db.enumerations()[std::size_t(p->enumeration)];
            const auto index = quint16(p->enumeration + 1);
            if (e.hasDisplayTexts()) {
                indices.displayIndex = index;
                indices.displayCount = quint16(e.definitions[0].texts.size());
            }
            indices.combivisIndex = index;
            indices.combivisCount = quint16(e.definitions.size());
        }
        return answer(request, Ack::Ok, indices);
    }
    default:
        break;
    }
    return answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
}

Telegram answerPlaintext(const DriveState &state, const Telegram &request)
{
    const ParameterDatabase &db = state.db();
    switch (request.service) {
    case Service::DisplayPlaintext: {
        const auto *d = request.as<DisplayPlaintextData>();
        if (!d)
            return malformed(request);
        DisplayPlaintextData result { d->index, d->subindex, d->language, 0, 0, {} };
        if (!validLanguage(d->language))
            return answer(request, Ack::LanguageInvalid, result);
        const Enumeration *e = db.enumerationAt(d->index);
        if (!e || !e->hasDisplayTexts() || d->subindex >= e->definitions[0].texts.size())
            return answer(request, Ack::DataInvalid, result);
        const Plaintext &text = e->definitions[0].texts[d->subindex];
        result.value = text.value;
        result.type = text.type;
        result.segments = text.display;
        if (state.displayTextAsCharacters()) {
            const QByteArray characters = sevenSegmentText(text.display).toLatin1().rightJustified(5, ' ');
            std::copy_n(characters.constData(), result.segments.size(), result.segments.begin());
        }
        return answer(request, Ack::Ok, result);
    }
    case Service::CombivisPlaintext: {
        const auto *d = request.as<CombivisPlaintextData>();
        if (!d)
            return malformed(request);
        CombivisPlaintextData result {
            d->index, d->definition, d->subindex, d->language, 0, 0, {}
        };
        if (!validLanguage(d->language))
            return answer(request, Ack::LanguageInvalid, result);
        const Enumeration *e = db.enumerationAt(d->index);
        if (!e || d->definition >= e->definitions.size()
            || d->subindex >= e->definitions[d->definition].texts.size())
            return answer(request, Ack::DataInvalid, result);
        const Plaintext &text = e->definitions[d->definition].texts[d->subindex];
        result.value = text.value;
        result.type = text.type;
        result.text = text.text[d->language];
        return answer(request, Ack::Ok, result);
    }
    case Service::PlaintextDefinition: {
        const auto *d = request.as<PlaintextDefinitionData>();
        if (!d)
            return malformed(request);
        PlaintextDefinitionData result { d->index, d->definition, d->language, 0, 0, {} };
        if (!validLanguage(d->language))
            return answer(request, Ack::LanguageInvalid, result);
        const Enumeration *e = db.enumerationAt(d->index);
        if (!e || d->definition >= e->definitions.size())
            return answer(request, Ack::DataInvalid, result);
        const PlaintextDefinitionEntry &definition = e->definitions[d->definition];
        result.mask = definition.mask;
        result.count = quint8(definition.texts.size());
        result.text = definition.description[d->language];
        if (result.text.isEmpty()) // a whole-value enumeration: its texts are the value's
            result.text = d->language == 0 ? QByteArrayLiteral("Value") : QByteArrayLiteral("Wert");
        return answer(request, Ack::Ok, result);
    }
    default:
        break;
    }
    return answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
}

Telegram answerGroup(const DriveState &state, const Telegram &request)
{
    if (request.service == Service::GroupProperties) {
        const auto *d = request.as<GroupPropertiesData>();
        if (!d)
            return malformed(request);
        const SimGroup *g = state.db().group(quint8(d->address >> 8));
        if (!g)
            return answer(request, Ack::AddressInvalid,
                          GroupPropertiesData { d->address, 0, {}, 0, 0, 0, 0 });
        return answer(request, Ack::Ok,
                      GroupPropertiesData { d->address, g->index, g->id, g->shortcut, g->properties,
                                            g->highestNumber, quint8(g->count - 1) });
    }
    const auto *d = request.as<NameData>();
    if (!d)
        return malformed(request);
    const SimGroup *g = state.db().group(quint8(d->address >> 8));
    if (!g)
        return answer(request, Ack::AddressInvalid, NameData { d->address, d->language, {} });
    if (!validLanguage(d->language))
        return answer(request, Ack::LanguageInvalid, NameData { d->address, d->language, {} });
    return answer(request, Ack::Ok, NameData { d->address, d->language, g->name[d->language] });
}

Telegram answerFieldbus(const Telegram &request, const QByteArray &identification)
{
    const auto *d = request.as<FieldbusData>();
    if (!d)
        return malformed(request);
    FieldbusData result { d->function, d->index, d->subindex, {} };
    if (request.isWrite() || d->function != kIdentifyFunction || identification.isEmpty())
        return answer(request, Ack::ServiceNotAvailable, result);
    result.data = identification.left(64);
    return answer(request, Ack::Ok, result);
}

} // namespace

Telegram answerMetadataService(const DriveState &state, const Telegram &request,
                               const QByteArray &identification)
{
    if (request.service == Service::Fieldbus)
        return answerFieldbus(request, identification);
    // Names, limits, properties, scaling and plaintexts belong to the drive: an operator
    // cannot write them.
    if (request.isWrite())
        return answer(request, Ack::ServiceNotAvailable, request.data);
    switch (request.service) {
    case Service::DisplayPlaintext:
    case Service::CombivisPlaintext:
    case Service::PlaintextDefinition:
        return answerPlaintext(state, request);
    case Service::GroupProperties:
    case Service::GroupName:
        return answerGroup(state, request);
    default:
        return answerParameterMetadata(state, request);
    }
}

} // namespace DriveDesk::Sim
