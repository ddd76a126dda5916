#pragma once

#include "parameters/ChosenValues.h"
#include "parameters/DriveDescription.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <functional>

namespace DriveDesk {

// What the compare window takes from the window it belongs to: the drive it is connected to and
// the parameter file it shows instead, and the ways to write into either. CompareFeature is the
// one in the main window; a test may bring its own.
class CompareHost
{
public:
    virtual ~CompareHost() = default;

    // A drive is connected and read.
    virtual bool hasDrive() const = 0;
    // The drive's parameters as the window holds them now.
    virtual DriveDescription drive() const = 0;
    // The parameter file the window shows instead of a drive, absolute; empty while none is.
    virtual QString shownFilePath() const = 0;
    // The file shown, with the changes not yet saved.
    virtual DriveDescription shownFile() const = 0;
    // Puts the values into the file shown as one undoable step of the window's edits (saved
    // when the user saves the file): the file on disk is never written behind the window's
    // back. How many values went in; the reasons of the others in `refusals`.
    virtual int writeToShownFile(const QList<ChosenValue> &values, QStringList *refusals) = 0;
    // A drive is connected and someone takes a selection to download.
    virtual bool canWriteToDrive() const = 0;
    // Asks for a parameter file to read, as the window asks for every file it opens; `chosen`
    // runs with its path.
    virtual void chooseFile(const QString &title, std::function<void(const QString &path)> chosen) = 0;
    // Hands the selection (ChosenValues::selectionFor) to the window's download, which checks,
    // shows a last look, writes and reports. Nothing is written here.
    virtual void writeToDrive(const DriveDescription &selection) = 0;
};

} // namespace DriveDesk
